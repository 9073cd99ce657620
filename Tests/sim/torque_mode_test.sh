#!/usr/bin/env bash
# tier: check (make check runs it: about 10 s)
# Torque mode in the sim (lockstep): the Hubo2+ standing, its right arm in torque mode
# (Tests/sim/torque_arm.lua): gravity compensation holds it, zero torque lets it fall, a torque beyond
# the limit is clamped, a NaN torque is refused, killing motion returns every joint to position mode
# holding the arm. Prints TAP and the figures.
#   Tests/sim/torque_mode_test.sh [ITERATIONS]
# ITERATIONS: dWorldQuickStep iterations through a site overlay (a solver setting, not physics; the
# body's own 40 without it): the same checks, for comparing the figures (Tests/sim/torque_converged_test.sh
# runs it with 400).
set -u
cd "$(dirname "$0")/../.."
source Run/env.sh
source Tests/tap_lib.sh
scenario_logs sim
iterations=${1:-}
id=$(( ${ROBOT_ID:-9300} + 70 ))
label=torque_arm
if [ -n "$iterations" ]; then
  label=torque_arm_$iterations
  solver_site "$iterations"
fi
ROBOT=hubo2plus lockstep_scenario "$id" "$label" Tests/sim/torque_arm.lua
echo "1..$k"
[ $failed -eq 0 ]
