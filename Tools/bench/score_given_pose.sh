#!/usr/bin/env bash
# Diagnostic benchmark: the scoring scenario (Tests/scenarios/score_test.sh, 10 seeds, lockstep)
# with the robot told its pose once when play starts (Tools/bench/behavior_given_pose.lua), so the
# figures show how the robot plays once localized. Prints each seed's outcome, goals/10 and the
# median time to goal; never fails on the figures. Logs in build/test-logs/bench-score/.
cd "$(dirname "$0")/../.."
SCORE_BEHAVIOR=Tools/bench/behavior_given_pose.lua SCORE_LOGDIR=build/test-logs/bench-score SKIP_KILL=1 \
  ROBOT_ID=${ROBOT_ID:-9200} bash Tests/scenarios/score_test.sh "$@" 2>/dev/null | grep '^# \(seed\|scored\)'
exit 0
