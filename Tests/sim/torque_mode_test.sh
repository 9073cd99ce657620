#!/usr/bin/env bash
# tier: check (make check runs it: about a minute)
# Torque mode in the sim (lockstep): the Hubo2+ standing, its right arm in torque mode
# (Tests/sim/torque_arm.lua): gravity compensation holds it, zero torque lets it fall, a torque beyond
# the limit is clamped, a NaN torque is refused, killing motion returns every joint to position mode
# holding the arm. Prints TAP and the figures.
set -u
cd "$(dirname "$0")/../.."
source Run/env.sh
source Tests/tap_lib.sh
LOGDIR="$HRP_ROOT/build/test-logs/sim"
mkdir -p "$LOGDIR"
failed=0; k=0
id=$(( ${ROBOT_ID:-9300} + 70 ))
Tools/shm/shm --robot "$id" remove >/dev/null 2>&1   # stale segments of an earlier run
ROBOT=hubo2plus ROBOT_ID=$id ./run_main --sim --quiet --no-restart --dcm-arg --lockstep-wait --dcm-arg 2 \
  --dcm-arg --no-camera motion >"$LOGDIR/main_torque_arm.log" 2>&1 &
main_pid=$!
for _ in $(seq 200); do grep -q 'motion started' "$LOGDIR/main_torque_arm.log" 2>/dev/null && break; sleep 0.1; done
ROBOT=hubo2plus ROBOT_ID=$id timeout 300 ./run_repl Tests/sim/torque_arm.lua >"$LOGDIR/torque_arm.log" 2>&1
rc=$?
kill -TERM "$main_pid" 2>/dev/null
wait "$main_pid" 2>/dev/null
Tools/shm/shm --robot "$id" remove >/dev/null 2>&1
tap_merge "$LOGDIR/torque_arm.log" torque_arm "$rc"
echo "1..$k"
[ $failed -eq 0 ]
