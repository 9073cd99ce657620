#!/usr/bin/env bash
# The white ball seen by the OP3 walking in the sim, the long run (Tests/vision/walk_eye_test.sh
# with 5 seeds of 120 s each: ~8700 frames with the ball fully in view): recall, false detections,
# range and bearing errors of the vision and of its pixel through other camera poses. Figures only
# (the goals print; the benchmark never fails on them).
#   [WALK_EYE_BALL=orange] Tools/bench/walk_eye.sh [SECONDS] [SEEDS...]
set -u
cd "$(dirname "$0")/../.."
SECONDS_RUN=${1:-120}
shift || true
SEEDS="${*:-1 2 3 4 5}"
WALK_EYE_GATE=none WALK_EYE_SECONDS=$SECONDS_RUN WALK_EYE_SEEDS="$SEEDS" ROBOT_ID=$(( ${ROBOT_ID:-9100} + 450 )) \
  bash Tests/vision/walk_eye_test.sh
