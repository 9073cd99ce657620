#!/usr/bin/env bash
# tier: check (make check runs it: a few seconds)
# The sim DCM through shared memory (TAP): lockstep determinism (same seed, same script: identical
# truth to the last bit), Sim requests, two robots in one world, two different bodies in one world
# (each its own description and joint order), NaN commands counted, a robot whose
# Lua side went away holds its pose (real time), clear errors for a bad robot file.
set -u
cd "$(dirname "$0")/../.."
source Run/env.sh
ID=${ROBOT_ID:-9300}
LOG="$HRP_ROOT/build/test-logs/sim"
mkdir -p "$LOG"
n=0; fails=0
ok() { n=$((n + 1)); echo "ok $n - $1"; }
nok() { n=$((n + 1)); fails=$((fails + 1)); echo "not ok $n - $1"; }
check() { if [ "$1" = 0 ]; then ok "$2"; else nok "$2"; fi; }
DCM_PID=
start_dcm() {   # start_dcm LOGNAME ARGS...
  local name=$1; shift
  "$HRP_BUILD/bin/dcm_sim" "$@" >"$LOG/$name.log" 2>&1 &
  DCM_PID=$!
  for _ in $(seq 100); do
    [ -n "$(luajit -e "local s=require('shm'); local b=s.open('dcm.sensor',{try=true,attach=true}); io.write(b and b.dcm_pid[0]==$DCM_PID and 'y' or '')" 2>/dev/null)" ] && return 0
    sleep 0.05
  done
  return 1
}
stop_dcm() {
  [ -n "$DCM_PID" ] && kill "$DCM_PID" 2>/dev/null && wait "$DCM_PID" 2>/dev/null
  DCM_PID=
}
cleanup() {
  stop_dcm
  for r in "$ID" $((ID + 1)); do ROBOT_ID=$r Tools/shm/shm remove >/dev/null 2>&1; done
}
trap cleanup EXIT

# ---- determinism: two lockstep runs, same seed, same script
for run in 1 2 3; do
  cleanup
  seed=5; [ "$run" = 3 ] && seed=6
  start_dcm "lockstep_$run" --lockstep --seed "$seed" --quiet || { nok "dcm_sim starts (run $run)"; continue; }
  timeout 120 ./run_repl Tests/sim/scenario_push.lua >"$LOG/scenario_$run.out" 2>&1
  echo "rc=$?" >>"$LOG/scenario_$run.out"
  stop_dcm
done
cat "$LOG/scenario_1.out" | sed 's/^/# run 1: /'
grep -q '^truth .* fallen=false' "$LOG/scenario_1.out" && grep -q 'rc=0' "$LOG/scenario_1.out"
check $? "lockstep scenario runs (reset, stance, teleport, push, wait, truth) and the robot stays up"
cmp -s <(grep -E '^(truth|ball|imu|tick)' "$LOG/scenario_1.out") <(grep -E '^(truth|ball|imu|tick)' "$LOG/scenario_2.out")
check $? "two lockstep runs with the same seed end with bit-identical truth, ball and IMU"
! cmp -s <(grep -E '^imu' "$LOG/scenario_1.out") <(grep -E '^imu' "$LOG/scenario_3.out")
check $? "another seed gives other sensor noise"
grep -q '^tick' "$LOG/scenario_1.out" && [ "$(grep '^tick' "$LOG/scenario_1.out")" = "$(grep '^tick' "$LOG/scenario_2.out")" ]
check $? "the scenario ends on the same tick in both runs"

# ---- two robots in one world; Sim requests; NaN commands
cleanup
if start_dcm two --lockstep --robots 2 --seed 1 --quiet; then
  out=$(timeout 60 ./run_repl -e '
    local shm = require("shm")
    assert(Sim.teleport_robot(-2, 1, 0.5))
    assert(Sim.teleport_ball(2, -1))
    wait(0.5)
    local t = Sim.truth()
    local other = shm.open("sim", { robot = shm.robot_id() + 1 })
    local sensor2 = shm.open("dcm.sensor", { robot = shm.robot_id() + 1 })
    print(string.format("me %.3f %.3f %.3f other %.3f %.3f ball %.3f %.3f ball2 %.3f tick2 %d",
      t.x, t.y, t.yaw, other.robot[0], other.robot[1], t.ball.x, t.ball.y, other.ball[0], sensor2.tick[0]))
    dcm_actuator.command[3] = 0/0
    dcm_actuator.command[4] = 1/0
    wait(0.2)
    print(string.format("nan %d fallen %s", dcm_stats.nan_commands[0], tostring(Sim.truth().fallen)))
    print("ok_end")' 2>&1)
  echo "$out" | sed 's/^/# /'
  echo "$out" | grep -q 'me -2.000 1.000 0.500 other 1.000 0.000 ball 2.000 -1.000 ball2 2.000'
  check $? "two robots in one world: each its own blocks, one ball, teleports land"
  echo "$out" | grep -Eq 'nan [1-9][0-9]* fallen false'
  check $? "NaN/inf commands are ignored and counted in dcm.stats.nan_commands"
  stop_dcm
else
  nok "dcm_sim starts with two robots"
fi

# ---- two different bodies in one world: op3 and a body "op3r" of the same description whose bus
# order is reversed (a test tree: Config/robots/op3r); each robot id gets its body's joint order
cleanup
tmp=$(mktemp -d)
cp -r Config Lib "$tmp/"
mkdir -p "$tmp/Config/robots/op3r"
cp Config/robots/op3/camera.lua "$tmp/Config/robots/op3r/"
cat >"$tmp/Config/robots/op3r/robot.lua" <<LUA
local t = dofile('$tmp/Config/robots/op3/robot.lua')
t.name = 'op3r'
t.description = '../op3/op3.urdf'
local rev = {}
for i = #t.joints, 1, -1 do rev[#rev + 1] = t.joints[i] end
t.joints = rev
return t
LUA
DCM_PID=
HRP_ROOT=$tmp "$HRP_BUILD/bin/dcm_sim" --lockstep --robots op3,op3r --seed 1 >"$LOG/bodies.log" 2>&1 &
DCM_PID=$!
sleep 1
out=$(timeout 60 ./run_repl -e '
  local shm = require("shm")
  local a2 = shm.open("dcm.actuator", { robot = shm.robot_id() + 1 })
  local s2 = shm.open("dcm.sensor", { robot = shm.robot_id() + 1 })
  wait(0.1)
  a2:write(function(a) a.command[19] = 0.5 end)   -- op3r: joint 20 of its order is head_pan
  wait(1.0)
  local other = shm.open("sim", { robot = shm.robot_id() + 1 })
  print(string.format("r2_head_pan %.3f r2_first %.3f r1_head_pan %.3f fallen %d %d", s2.position[19], s2.position[0],
    Body.get_position("head_pan"), Sim.truth().fallen and 1 or 0, other.fallen[0]))' 2>&1)
stop_dcm
echo "$out" | sed 's/^/# /'
head -1 "$LOG/bodies.log" | sed 's/^/# /'
grep -q "op3 $ID, op3r $((ID + 1))" "$LOG/bodies.log" && echo "$out" | grep -Eq 'r2_head_pan 0\.(49|50)[0-9] r2_first -?0\.00[0-9] r1_head_pan -?0\.00[0-9] fallen 0 0'
check $? "two bodies in one world: each robot id its body's joint order (op3 and op3r)"
err=$(HRP_ROOT=$tmp timeout 10 "$HRP_BUILD/bin/dcm_sim" --robots op3,nobody --quiet 2>&1)
echo "# $err"
echo "$err" | grep -q "unknown robot 'nobody'"
check $? "an unknown body in --robots is named"
rm -rf "$tmp"

# ---- real time: the Lua side sets the stance and goes away; the robot holds its pose
cleanup
if start_dcm realtime --quiet; then
  ./run_repl -e 'local st = dofile(os.getenv("HRP_ROOT") .. "/Tests/sim/stance.lua"); st.command(Body); dcm_actuator.tick_ack[0] = Body.get_tick()' >/dev/null 2>&1
  sleep 2.5
  out=$(./run_repl -e '
    -- the stance, but where the body has a safe pose the DCM ramps its joints there on the trip
    local q = dofile(os.getenv("HRP_ROOT") .. "/Tests/sim/stance.lua").pose()
    local safe = rawget(require("Config").load("robot"), "safe_pose")
    for n, v in pairs(safe and safe.q or {}) do q[n] = v end
    local err = 0
    for _, n in ipairs(Body.joint_names()) do err = math.max(err, math.abs(Body.get_position(n) - (q[n] or 0))) end
    local t = Sim.truth()
    print(string.format("time %.2f err %.4f fallen %s trips %d rate %.1f", Body.get_time(), err, tostring(t.fallen),
      dcm_stats.watchdog_trips[0], dcm_stats.rate[0]))' 2>&1)
  echo "$out" | sed 's/^/# /'
  # at the safe hardness (0.3) the crouch sags under the robot's weight (0.07 rad measured): < 0.1 rad
  echo "$out" | grep -Eq 'err 0\.0[0-9]+ fallen false trips [1-9]'
  check $? "real time: with its Lua side gone the robot takes its safe pose and stays up (watchdog trip counted)"
  err=$(timeout 10 "$HRP_BUILD/bin/dcm_sim" --quiet 2>&1); rc=$?
  echo "# second DCM: $err"
  [ $rc -ne 0 ] && echo "$err" | grep -q "another DCM (pid $DCM_PID) is running"
  check $? "a second DCM on the same robot id is refused, naming the running one's pid"
  stop_dcm
else
  nok "dcm_sim starts in real time"
fi

# ---- real time: the motion process killed (-9) mid-stance: the DCM sees its writer die and holds
# the pose on its next cycle, long before the tick_ack timeout
cleanup
if start_dcm kill_motion; then
  ./run_main --no-restart --quiet motion >"$LOG/kill_motion_main.log" 2>&1 &
  main_pid=$!
  out=$(./run_repl -e '
    local shm = require("shm")
    local m = shm.open("motion")
    for _ = 1, 100 do if m.tick[0] > 0 and dcm_actuator.writer_pid[0] == m.pid[0] then break end wait(0.05) end
    wait(1.0)
    local pid = m.pid[0]
    local trips = dcm_stats.watchdog_trips[0]
    local t0 = shm.C.shm_now()
    os.execute("kill -9 " .. pid)
    while dcm_stats.watchdog_trips[0] == trips and shm.C.shm_now() - t0 < 2 do end
    print(string.format("motion pid %d killed: safe state after %.1f ms (writer_pid %d)", pid,
      (shm.C.shm_now() - t0) * 1e3, dcm_actuator.writer_pid[0]))' 2>&1)
  kill "$main_pid" 2>/dev/null; wait "$main_pid" 2>/dev/null
  echo "$out" | sed 's/^/# /'
  pid=$(echo "$out" | sed -n 's/^motion pid \([0-9]*\) killed.*/\1/p')
  [ -n "$pid" ] && grep -q "watchdog: the writer (pid $pid) died" "$LOG/kill_motion.log"
  check $? "motion killed: the DCM trips its watchdog on the writer's death (not the tick_ack timeout)"
  stop_dcm
else
  nok "dcm_sim starts (kill motion)"
fi

# ---- the DCM owns its start state: a REPL command written before any DCM ran (hardness 0, torque
# off, zero pose) does not survive its start; the robot stands either way
for order in repl_first dcm_first; do
  cleanup
  write_limp='for _, n in ipairs(Body.joint_names()) do Body.set_command(n, 0) end
    dcm_actuator:write(function(a) for j = 0, #Body.joint_names() - 1 do a.hardness[j] = 0; a.torque_enable[j] = 0 end end)'
  [ $order = repl_first ] && ./run_repl -e "$write_limp" >/dev/null 2>&1
  if start_dcm "start_$order" --quiet; then
    sleep 0.3
    out=$(./run_repl -e '
      local h, te = 1, 1
      for j = 0, #Body.joint_names() - 1 do h = math.min(h, dcm_actuator.hardness[j]); te = math.min(te, dcm_actuator.torque_enable[j]) end
      dcm_actuator.tick_ack[0] = Body.get_tick()
      local z0 = Sim.truth().z
      for _ = 1, 30 do dcm_actuator.tick_ack[0] = Body.get_tick(); wait(0.1) end
      local t = Sim.truth()
      print(string.format("hardness %.2f torque %d fallen %s dz %.3f", h, te, tostring(t.fallen), t.z - z0))' 2>&1)
    echo "$out" | sed "s/^/# $order: /"
    echo "$out" | grep -Eq 'hardness 1.00 torque 1 fallen false dz -?0\.00[0-9]'
    check $? "the DCM's start state ($order): every joint at start_hardness, torque on; the robot stands 3 s"
    stop_dcm
  else
    nok "dcm_sim starts ($order)"
  fi
done

# ---- a bad robot file stops start-up with the file and the element named
tmp=$(mktemp -d)
cp -r Config "$tmp/"
sed 's#<mass value="1.34928"/>##' Config/robots/op3/op3.urdf >"$tmp/Config/robots/op3/op3.urdf"
cp -r Lib "$tmp/"
err=$(HRP_ROOT=$tmp HRP_SCHEMA=$HRP_ROOT/Config/shm.schema timeout 10 "$HRP_BUILD/bin/dcm_sim" --quiet 2>&1)
rc=$?
echo "# $err"
[ $rc -ne 0 ] && echo "$err" | grep -q "op3.urdf" && echo "$err" | grep -q "body_link"
check $? "a robot file with a missing <mass> stops start-up naming file and link"
rm -f "$tmp/Config/robots/op3/op3.urdf"
err=$(HRP_ROOT=$tmp timeout 10 "$HRP_BUILD/bin/dcm_sim" --quiet 2>&1)
rc=$?
echo "# $err"
[ $rc -ne 0 ] && echo "$err" | grep -q "op3.urdf"
check $? "a missing robot file stops start-up naming the file"
rm -rf "$tmp"

echo "1..$n"
[ $fails -eq 0 ]
