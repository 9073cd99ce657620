#!/usr/bin/env bash
# tier: test
# The HOAP-3's walk pattern generated ahead and played back, as its OpenHRP3 study did (S0 in
# Config/robots/hoap3/hoap3_reference.txt): Tools/pattern/gen_pattern.lua runs the preview
# controller offline over 12 steps forward (z_c = 0.32 m, T = 5 ms, N = 300, R/Q = 1e-5:
# Config/robots/hoap3/pattern.lua) into a joint trajectory file; the motion state `pattern` plays it
# in the sim's lockstep (Tests/motion/pattern_scenario.lua: no fall, the whole file, the distance;
# the planned against measured ZMP and joint angles printed and bounded). Writes the trajectory, the
# log and two PNGs (the left leg's joint angles, the ZMP) into build/test-logs/motion/.
set -u
cd "$(dirname "$0")/../.."
# its sim and motion process on robot id ROBOT_ID+98 (default 9298)
id=$(( ${ROBOT_ID:-9200} + 98 ))
export ROBOT=hoap3
source Run/env.sh
source Tests/tap_lib.sh
LOGDIR="$HRP_ROOT/build/test-logs/motion"
mkdir -p "$LOGDIR"
PATTERN="$LOGDIR/hoap3_pattern.csv"
LOG="$LOGDIR/hoap3_pattern_play.csv"
k=0; failed=0

if [ ! -x build/bin/dcm_sim ]; then
  echo "not ok 1 - pattern: the simulator (build/bin/dcm_sim) is not built"
  exit 1
fi
k=$((k + 1))
if luajit Tools/pattern/gen_pattern.lua "$PATTERN" >"$LOGDIR/hoap3_pattern_gen.log" 2>&1; then
  echo "ok $k - pattern: generated ($PATTERN)"
  cat "$LOGDIR/hoap3_pattern_gen.log"
else
  echo "not ok $k - pattern: Tools/pattern/gen_pattern.lua failed"
  sed 's/^/#   /' "$LOGDIR/hoap3_pattern_gen.log"
  exit 1
fi

SCENARIO_TIMEOUT=600 SCENARIO_DCM_ARGS="--seed ${SIM_SEED:-1}" \
  lockstep_scenario "$id" pattern Tests/motion/pattern_scenario.lua "$PATTERN" "$LOG"

k=$((k + 1))
if python3 Tools/plot/plot_pattern.py "$LOG" "$LOGDIR/hoap3_pattern" l 'HOAP-3, 12 steps' 0.068,0.040,0.0315,0.0415 pressure >"$LOGDIR/plot_pattern.log" 2>&1 \
  && [ -s "$LOGDIR/hoap3_pattern_joints.png" ]; then
  echo "ok $k - pattern: plotted $LOGDIR/hoap3_pattern_joints.png, $LOGDIR/hoap3_pattern_zmp.png"
else
  failed=$((failed + 1))
  echo "not ok $k - pattern: plot failed"
  sed 's/^/#   /' "$LOGDIR/plot_pattern.log"
fi
[ $failed -eq 0 ]
