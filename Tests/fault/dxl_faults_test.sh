#!/usr/bin/env bash
# Scenario (make test, real time): faults against the Dynamixel bus. The OP DCM (PLATFORM=OP, the
# OP3's XM430 chain) drives Platforms/OP/emulator/dxl_emulator, whose --trace says when each servo received what;
# `./run_main motion` supervises the motion process. Faults: kill -9 of motion while it walks and
# while it stands, and kill -9 of the DCM under the running motion process (the DCM restarted by
# hand, as a robot's start script would). Prints, from the bus's side:
#   safe_ms     wall ms from the kill to the last servo receiving the safe state's hardness
#               (dcm.lua safe_hardness of the P gain); the goal is 50 ms
#   back_s      s from the kill until the restarted motion's commands reach the servos again
#               (every servo's hardness above the safe state's, and the walk's goals changing)
#   dcm: the bus's silence, and from the DCM's restart to its first goals on the bus; motion's pid
#   unchanged and its commands flowing again.
#   env: ROBOT_ID (uses ROBOT_ID+90 and +91)
set -u
cd "$(dirname "$0")/../.."
source Run/env.sh
export PLATFORM=OP ROBOT=op3
ID=$(( ${ROBOT_ID:-9200} + 90 ))
export ROBOT_ID=$ID
LOGDIR="$HRP_ROOT/build/test-logs/fault"
mkdir -p "$LOGDIR"
T=$(mktemp -d)
TRACE=$LOGDIR/dxl_trace.txt
EMU="" DCM="" MAIN=""
n=0 fails=0
ok() { n=$((n + 1)); if [ "$1" = 0 ]; then echo "ok $n - $2"; else echo "not ok $n - $2"; fails=$((fails + 1)); fi; }
cleanup() {
  [ -n "$MAIN" ] && kill -TERM "$MAIN" 2>/dev/null
  [ -n "$DCM" ] && kill -TERM "$DCM" 2>/dev/null
  [ -n "$EMU" ] && kill -TERM "$EMU" 2>/dev/null
  wait 2>/dev/null
  rm -rf "$T"
  Tools/shm/shm --robot "$ID" remove >/dev/null 2>&1
}
trap cleanup EXIT
if [ ! -x build/bin/dcm_op ] || [ ! -x build/bin/dxl_emulator ]; then
  echo "1..1"; echo "ok 1 # SKIP needs build/bin/dcm_op and build/bin/dxl_emulator"; exit 0
fi
SAFE=$(luajit -e 'print(math.floor(require("Config").load("dcm").safe_hardness * 800 + 0.5))')   # XM P gain 800 = 1
wall() { date +%s.%N; }
repl() { timeout 20 ./run_repl -e "$1" 2>&1 | tail -1; }
# wait_until SECONDS CMD...: polls CMD every 20 ms
wait_until() { local end=$((SECONDS + $1)); shift; until "$@" >/dev/null; do [ $SECONDS -ge $end ] && return 1; sleep 0.02; done; }
# hardness_all T0 VALUE [above]: every servo received hardness VALUE (above: more than VALUE) after
# T0; prints the time the last one did
hardness_all() {
  awk -v t0="$1" -v v="$2" -v above="${3:-}" '$1 > t0 && $3 == "hardness" && (above ? $4 > v : $4 == v) {
      if (!($2 in s)) { s[$2] = 1; n++; last = $1 } }
    END { if (n >= 20) { printf "%.6f\n", last; exit 0 } exit 1 }' "$TRACE"
}
# goals_after T0: number of packets that changed goals after T0
goals_after() { awk -v t0="$1" '$1 > t0 && $2 == "goals" { n++ } END { print n + 0 }' "$TRACE"; }
has_goals_after() { [ -n "$(first_goals_after "$1")" ]; }
first_goals_after() { awk -v t0="$1" '$1 > t0 && $2 == "goals" { printf "%.6f\n", $1; exit }' "$TRACE"; }
# start_walk: asks motion to walk until it says it does (a request in its first moments may be
# taken before its start-up is done), then until the goals change on the bus
start_walk() {
  for _ in $(seq 20); do
    [ "$(repl "Motion.request('walk'); Walk.set_velocity(0.15, 0, 0); print(Motion.walking())")" = true ] && break
    sleep 0.5
  done
  wait_until 20 walking
}
# walking: the goals changed in 40 packets of the last 0.5 s (the DCM's 125 Hz: 62)
walking() { local t; t=$(awk -v w="$(wall)" 'BEGIN { printf "%.6f", w - 0.5 }'); [ "$(goals_after "$t")" -ge 40 ]; }
motion_pid() { sed -nE 's/.*motion started \(pid ([0-9]+)\).*/\1/p' "$LOGDIR/dxl_main.log" | tail -1; }
motion_restarted() { [ "$(motion_pid)" != "$1" ] && [ -n "$(motion_pid)" ]; }
secs() { [ -n "$2" ] && awk -v a="$1" -v b="$2" 'BEGIN { printf "%.2f", b - a }' || echo never; }
ms() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.1f", (b - a) * 1000 }'; }

Tools/shm/shm --robot "$ID" remove >/dev/null 2>&1
mkfifo "$T/emu.in"
build/bin/dxl_emulator --link "$T/dxl" --protocol 2 --stdin --realtime --quiet --trace "$TRACE" \
  <"$T/emu.in" >"$T/emu.out" 2>"$LOGDIR/dxl_emu.log" &
EMU=$!
exec 3>"$T/emu.in"
wait_until 5 test -e "$T/dxl"
start_dcm() { ./run_dcm --port "$T/dxl" --quiet >>"$LOGDIR/dxl_dcm.log" 2>&1 & DCM=$!; }
: >"$LOGDIR/dxl_dcm.log"
start_dcm
wait_until 10 test -e "/dev/shm/hrp.$ID.dcm.sensor"
./run_main --quiet motion >"$LOGDIR/dxl_main.log" 2>&1 &
MAIN=$!
wait_until 20 grep -q 'motion started' "$LOGDIR/dxl_main.log"
ok $? "the OP DCM and motion run against the emulated OP3 bus"

# kill_motion WHAT: motion in state WHAT (walk|stand), killed; the figures from the trace
kill_motion() {
  local what=$1
  if [ "$what" = walk ]; then start_walk
  else repl "Walk.set_velocity(0, 0, 0); Motion.request('stand')" >/dev/null; fi
  sleep 2
  local t1 goals pid t0 safe back
  t1=$(wall); sleep 1; goals=$(goals_after "$t1")
  pid=$(motion_pid)
  t0=$(wall)
  kill -9 "$pid"
  safe=""; wait_until 5 hardness_all "$t0" "$SAFE" && safe=$(hardness_all "$t0" "$SAFE")
  ok "$([ -n "$safe" ]; echo $?)" "kill -9 motion ($what, pid $pid, goals changing in $goals packets/s before): safe state on the bus after $( [ -n "$safe" ] && ms "$t0" "$safe" || echo never) ms (hardness $SAFE of 800 on all 20 servos)"
  [ -n "$safe" ] && echo "# figure: kill:motion:$what safe_ms=$(ms "$t0" "$safe")"
  wait_until 20 motion_restarted "$pid"
  ok $? "run_main restarts motion (pid $pid -> $(motion_pid))"
  back=""; wait_until 10 hardness_all "$t0" "$SAFE" above && back=$(hardness_all "$t0" "$SAFE" above)
  local walk=""; start_walk && walk=$(wall)
  ok "$([ -n "$back" ] && [ -n "$walk" ]; echo $?)" "the restarted motion's commands reach the servos: its hardness (above the safe state's) $(secs "$t0" "$back") s after the kill; walking again (asked once it ran) $(secs "$t0" "$walk") s after"
  echo "# figure: kill:motion:$what back_s=$(secs "$t0" "$back") walking_s=$(secs "$t0" "$walk")"
}
kill_motion walk
kill_motion stand

# the DCM killed under the running motion process, and restarted
pid=$(motion_pid)
sleep 2
t0=$(wall)
kill -9 "$DCM"; wait "$DCM" 2>/dev/null
last=$(awk '$2 == "goals" { t = $1 } END { printf "%.6f\n", t }' "$TRACE")
sleep 1
t1=$(wall)
silent=$(goals_after "$(awk -v a="$t0" 'BEGIN { printf "%.6f", a + 0.1 }')")   # after the signal's way
start_dcm
wait_until 10 has_goals_after "$t1"
first=$(first_goals_after "$t1")
start_walk
t2=$(wall); sleep 1
after=$(goals_after "$t2")
ok "$([ "$silent" -eq 0 ]; echo $?)" "kill -9 of the DCM: the bus goes quiet (its last goals at $(ms "$t0" "$last") ms from the kill signal; $silent goal packets from 0.1 s to 1 s)"
ok "$([ -n "$first" ]; echo $?)" "the restarted DCM drives the bus $( [ -n "$first" ] && ms "$t1" "$first" || echo never) ms after its start"
ok "$([ "$(motion_pid)" = "$pid" ] && kill -0 "$pid" 2>/dev/null; echo $?)" "motion was not restarted (pid $pid -> $(motion_pid))"
ok "$([ "$after" -gt 20 ]; echo $?)" "motion's walk reaches the servos through the new DCM ($after goal packets/s)"
[ -n "$first" ] && echo "# figure: kill:dcm first_goals_ms=$(ms "$t1" "$first") goals_per_s_after=$after"
grep -iE 'error|stale|layout' "$LOGDIR/dxl_main.log" | head -5 | sed 's/^/# main: /'
echo "1..$n"
[ $fails -eq 0 ]
