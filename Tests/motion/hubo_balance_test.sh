#!/usr/bin/env bash
# The Hubo2+'s balance on its ankle F/T sensors (Player/Motion/balance.lua) in the sim's lockstep:
# the ZMP error (measured on the feet's sensors minus the walk's reference) standing, leaned on by
# a steady push, walking, walking against a steady push, with the feedback off and on in the same
# run (Tests/motion/balance_scenarios.lua zmp): no falls, and the feedback reduces the error.
# SCENARIO push: the largest short push survived, off and on (figures; `make bench`: hubo_balance_push).
#   [ROBOT_ID=N] [SIM_SEED=N] Tests/motion/hubo_balance_test.sh [zmp|push]
set -u
cd "$(dirname "$0")/../.."
source Run/env.sh
export ROBOT=hubo2plus
LOGDIR="$HRP_ROOT/build/test-logs/motion"
mkdir -p "$LOGDIR"
id=$(( ${ROBOT_ID:-9200} + 90 ))
what=${1:-zmp}
Tools/shm/shm --robot "$id" remove >/dev/null 2>&1
ROBOT_ID=$id ./run_main --sim --quiet --no-restart --dcm-arg --lockstep-wait --dcm-arg 2 --dcm-arg --seed \
  --dcm-arg "${SIM_SEED:-1}" --dcm-arg --no-camera motion >"$LOGDIR/main_balance_$what.log" 2>&1 &
main_pid=$!
for _ in $(seq 200); do
  grep -q 'motion started' "$LOGDIR/main_balance_$what.log" 2>/dev/null && break
  sleep 0.1
done
ROBOT_ID=$id timeout 600 ./run_repl Tests/motion/balance_scenarios.lua "$what" 2>&1 | tee "$LOGDIR/balance_$what.log"
rc=${PIPESTATUS[0]}
kill -TERM "$main_pid" 2>/dev/null
wait "$main_pid" 2>/dev/null
Tools/shm/shm --robot "$id" remove >/dev/null 2>&1
[ "$rc" -eq 0 ] && ! grep -q '^not ok' "$LOGDIR/balance_$what.log"
