#!/usr/bin/env bash
# tier: check (make check runs it: a few seconds)
# Whole-body control in the sim (lockstep): the OP3 shifts its centre of mass over one foot, lifts
# the other 5 cm and holds 10 s (Tests/wbc/op3_foot_lift.lua prints TAP and the figures).
set -u
cd "$(dirname "$0")/../.."
source Run/env.sh
LOGDIR="$HRP_ROOT/build/test-logs/wbc"
mkdir -p "$LOGDIR"
id=$(( ${ROBOT_ID:-9200} + 80 ))
Tools/shm/shm --robot "$id" remove >/dev/null 2>&1   # stale segments of an earlier run
ROBOT=op3 ROBOT_ID=$id ./run_main --sim --quiet --no-restart --dcm-arg --lockstep-wait --dcm-arg 2 \
  --dcm-arg --no-camera motion >"$LOGDIR/main_op3.log" 2>&1 &
main_pid=$!
for _ in $(seq 200); do grep -q 'motion started' "$LOGDIR/main_op3.log" 2>/dev/null && break; sleep 0.1; done
ROBOT=op3 ROBOT_ID=$id timeout 300 ./run_repl Tests/wbc/op3_foot_lift.lua
rc=$?
kill -TERM "$main_pid" 2>/dev/null
wait "$main_pid" 2>/dev/null
Tools/shm/shm --robot "$id" remove >/dev/null 2>&1
exit $rc
