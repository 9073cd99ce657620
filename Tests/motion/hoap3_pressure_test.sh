#!/usr/bin/env bash
# tier: test (about 30 s: 6 s of robot time standing and leaning)
# The HOAP-3's foot pressure sensors (four under each foot: robot.lua foot_pressure, the sim's model
# in Platforms/Sim/pressure.h) against the sim's truth (lockstep): standing, the sensors' centre of
# pressure and the motion process's measured ZMP within a few mm of the truth's and inside the soles;
# shifting the weight sideways moves it and the sensors follow (Tests/motion/hoap3_pressure.lua).
# Writes the log and a PNG of the sensors' centre of pressure against the truth's into
# build/test-logs/motion/.
#   Tests/motion/hoap3_pressure_test.sh
set -u
cd "$(dirname "$0")/../.."
source Run/env.sh
source Tests/tap_lib.sh
scenario_logs motion
LOG="$LOGDIR/hoap3_pressure.csv"
ROBOT=hoap3 lockstep_scenario $(( ${ROBOT_ID:-9200} + 94 )) hoap3_pressure Tests/motion/hoap3_pressure.lua "$LOG"
k=$((k + 1))
if python3 Tools/plot/plot_cop.py "$LOG" "$LOGDIR/hoap3_pressure_cop.png" 'HOAP-3 standing, the weight shifted' \
    >"$LOGDIR/plot_cop.log" 2>&1 && [ -s "$LOGDIR/hoap3_pressure_cop.png" ]; then
  echo "ok $k - pressure: plotted $LOGDIR/hoap3_pressure_cop.png"
else
  failed=$((failed + 1))
  echo "not ok $k - pressure: plot failed"
  sed 's/^/#   /' "$LOGDIR/plot_cop.log"
fi
echo "1..$k"
[ $failed -eq 0 ]
