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
scenario_logs wbc
[ $# -eq 0 ] && set -- op3_foot_lift hubo_reach
j=0
for s in "$@"; do
  case $s in op3_*) body=op3 ;; hubo_*) body=hubo2plus ;; *) echo "unknown scenario $s"; exit 2 ;; esac
  ROBOT=$body lockstep_scenario $(( ${ROBOT_ID:-9200} + 80 + j )) "$s" "Tests/wbc/$s.lua"
  j=$((j + 1))
done
[ $failed -eq 0 ]
