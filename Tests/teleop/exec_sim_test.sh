#!/usr/bin/env bash
# tier: check (make check runs it: about 10 s)
# Teleoperation's executor in the sim (lockstep): the Hubo2+ plays the validated key pose "reach"
# (the palm within 2 cm of its target), refuses a corrupted trajectory and holds when stopped
# mid-trajectory (Tests/teleop/hubo_reach_exec.lua). Prints TAP and the figures.
set -u
cd "$(dirname "$0")/../.."
source Run/env.sh
source Tests/tap_lib.sh
scenario_logs teleop
ROBOT=hubo2plus lockstep_scenario $(( ${ROBOT_ID:-9200} + 90 )) hubo_reach_exec Tests/teleop/hubo_reach_exec.lua
[ $failed -eq 0 ]
