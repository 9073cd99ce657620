#!/usr/bin/env bash
# tier: test (make test runs it: about 70 s of sim time)
# Torque mode on the Hubo2+'s right arm inside whole-body control, in the sim (lockstep, the body's own
# solver settings): gravity compensation with zero task gains holds the arm, the palm tracks a circle,
# a push on the palm moves it by F/K and it returns, torques within the limits, the watchdog
# (Tests/wbc/hubo_arm_torque.lua). Prints TAP and the figures.
#   Tests/wbc/hubo_arm_torque_test.sh [ITERATIONS]
# ITERATIONS: dWorldQuickStep iterations through a site overlay (a solver setting, not physics; the
# body's own 40 without it): the same checks and bounds, for comparing the figures (docs/whole-body.md).
set -u
cd "$(dirname "$0")/../.."
source Run/env.sh
source Tests/tap_lib.sh
scenario_logs wbc
s=hubo_arm_torque
iterations=${1:-}
if [ -n "$iterations" ]; then
  # a solver setting, for comparison (the figures in docs/whole-body.md)
  s=hubo_arm_torque_$iterations
  solver_site "$iterations"
fi
ROBOT=hubo2plus SCENARIO_TIMEOUT=600 lockstep_scenario $(( ${ROBOT_ID:-9200} + 77 )) "$s" Tests/wbc/hubo_arm_torque.lua
echo "1..$k"
[ $failed -eq 0 ]
