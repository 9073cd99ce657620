#!/usr/bin/env bash
# Figures (not in make test: N sim runs): how often the robot falls when motion dies mid-walk and the
# DCM's safe state takes over. Each run: the sim in real time (the watchdog is off in lockstep),
# `./run_main --sim --no-restart motion`, a walk at 0.15 m/s, motion killed (kill -9) at a random
# moment 3-5 s into the walk, the sim's truth watched for 4 s after: fallen or not.
#   [CATCH_RUNS=4] [CATCH_SEED=1] [ROBOT=op3] Tools/bench/catch_falls.sh
# Prints one line per run and "falls: F of N"; exits 1 if a run did not run to its end. The safe state is the body's (robot.lua safe_pose:
# none = hold the pose of the trip; HRP_SITE can point to a site layer that changes it).
set -u
cd "$(dirname "$0")/../.."
source Run/env.sh
ID=$(( ${ROBOT_ID:-9200} + 97 ))
export ROBOT_ID=$ID HRP_GC_PORT=$((40000 + ID % 20000)) HRP_GC_RETURN_PORT=$((40001 + ID % 20000))
export HRP_TEAM_PORT=$((30000 + ID % 20000))
RUNS=${CATCH_RUNS:-4}
RANDOM=${CATCH_SEED:-1}
LOG="$HRP_ROOT/build/test-logs/fault/catch_main.log"
mkdir -p "$(dirname "$LOG")"
MAIN=""
trap '[ -n "$MAIN" ] && kill -TERM "$MAIN" 2>/dev/null; wait 2>/dev/null; Tools/shm/shm --robot "$ID" remove >/dev/null 2>&1' EXIT
falls=0
errors=0
for run in $(seq "$RUNS"); do
  delay=$(awk -v r=$RANDOM 'BEGIN { printf "%.2f", 3 + 2 * r / 32767 }')
  Tools/shm/shm --robot "$ID" remove >/dev/null 2>&1
  ./run_main --sim --no-restart --quiet --dcm-arg --no-camera motion >"$LOG" 2>&1 &
  MAIN=$!
  for _ in $(seq 300); do grep -q 'motion started' "$LOG" && break; sleep 0.1; done
  out=$(timeout 120 ./run_repl -e "
    local ffi = require('ffi')
    ffi.cdef('int kill(int pid, int sig);')
    local shm = require('shm')
    local a = shm.open('dcm.actuator')
    for _ = 1, 50 do Motion.request('walk') Walk.set_velocity(0.15, 0, 0) wait(0.2) if Motion.walking() then break end end
    wait($delay)
    local before = Sim.truth()
    ffi.C.kill(a.writer_pid[0], 9)
    local fell_at
    for k = 1, 40 do wait(0.1) if not fell_at and Sim.truth().fallen then fell_at = k * 0.1 end end
    print(string.format('at x = %.2f m, fallen=%s%s', before.x, tostring(fell_at ~= nil),
      fell_at and string.format(' (%.1f s after the kill)', fell_at) or ''))" 2>&1 | tail -1)
  kill -TERM "$MAIN" 2>/dev/null; wait "$MAIN" 2>/dev/null; MAIN=""
  echo "run $run: kill after ${delay} s of walking: $out"
  case $out in
    *fallen=true*) falls=$((falls + 1)) ;;
    *fallen=false*) ;;
    *) errors=$((errors + 1)); echo "run $run did not run (see $LOG)" ;;
  esac
done
echo "falls: $falls of $((RUNS - errors))$([ "$errors" -gt 0 ] && echo ", $errors runs failed")"
[ "$errors" -eq 0 ]
