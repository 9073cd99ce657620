#!/usr/bin/env bash
# A body of another shape (Config/robots/waistbot: the OP3 plus a waist yaw carrying the arms and
# head, a wrist per arm, the bus order legs first and waist last) stands and walks in the sim
# (lockstep) on the same motion code; the waist, which no motion state drives, holds a command
# from outside (Tests/motion/waist_scenario.lua prints TAP).
set -u
cd "$(dirname "$0")/../.."
export ROBOT=waistbot
source Run/env.sh
LOGDIR="$HRP_ROOT/build/test-logs/motion"
mkdir -p "$LOGDIR"
id=$(( ${ROBOT_ID:-9200} + 60 ))
Tools/shm/shm --robot "$id" remove >/dev/null 2>&1   # stale segments of an earlier run
ROBOT_ID=$id ./run_main --sim --quiet --no-restart --dcm-arg --lockstep-wait --dcm-arg 2 --dcm-arg --no-camera motion \
  >"$LOGDIR/main_waist.log" 2>&1 &
main_pid=$!
for _ in $(seq 200); do grep -q 'motion started' "$LOGDIR/main_waist.log" 2>/dev/null && break; sleep 0.1; done
ROBOT_ID=$id timeout 300 ./run_repl Tests/motion/waist_scenario.lua
rc=$?
kill -TERM "$main_pid" 2>/dev/null
wait "$main_pid" 2>/dev/null
Tools/shm/shm --robot "$id" remove >/dev/null 2>&1
exit $rc
