#!/usr/bin/env bash
# tier: check (make check runs it: a few seconds)
# Whole-body control in the sim (lockstep), each scenario in its own sim: the OP3 shifts its centre of
# mass over one foot, lifts the other 5 cm and holds 10 s (Tests/wbc/op3_foot_lift.lua); the Hubo2+
# reaches five hand targets while standing (Tests/wbc/hubo_reach.lua); Tests/wbc/skill_sim_test.sh runs
# the Hubo2+ waving (hubo_hello_bye). Each prints TAP and figures.
#   Tests/wbc/wbc_sim_test.sh [op3_foot_lift|hubo_reach|hubo_hello_bye ...]
set -u
cd "$(dirname "$0")/../.."
source Run/env.sh
source Tests/tap_lib.sh
LOGDIR="$HRP_ROOT/build/test-logs/wbc"
mkdir -p "$LOGDIR"
[ $# -eq 0 ] && set -- op3_foot_lift hubo_reach
failed=0; k=0; j=0
for s in "$@"; do
  case $s in op3_*) body=op3 ;; hubo_*) body=hubo2plus ;; *) echo "unknown scenario $s"; exit 2 ;; esac
  id=$(( ${ROBOT_ID:-9200} + 80 + j ))
  j=$((j + 1))
  Tools/shm/shm --robot "$id" remove >/dev/null 2>&1   # stale segments of an earlier run
  ROBOT=$body ROBOT_ID=$id ./run_main --sim --quiet --no-restart --dcm-arg --lockstep-wait --dcm-arg 2 \
    --dcm-arg --no-camera motion >"$LOGDIR/main_$s.log" 2>&1 &
  main_pid=$!
  for _ in $(seq 200); do grep -q 'motion started' "$LOGDIR/main_$s.log" 2>/dev/null && break; sleep 0.1; done
  ROBOT=$body ROBOT_ID=$id timeout 300 ./run_repl "Tests/wbc/$s.lua" >"$LOGDIR/$s.log" 2>&1
  rc=$?
  kill -TERM "$main_pid" 2>/dev/null
  wait "$main_pid" 2>/dev/null
  Tools/shm/shm --robot "$id" remove >/dev/null 2>&1
  tap_merge "$LOGDIR/$s.log" "$s" "$rc"
done
[ $failed -eq 0 ]
