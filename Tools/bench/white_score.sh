#!/usr/bin/env bash
# The scoring scenario (Tests/scenarios/score_test.sh: 10 seeded starts) with today's white ball:
# the sim renders it and the vision finds it by candidates and the classifier (the site folder
# Tests/scenarios/site_white sets ball.kind = 'white' for both). Prints each seed and the count.
#   Tools/bench/white_score.sh [SEEDS...]      (long: ~10 runs of up to 120 s of sim time)
set -u
cd "$(dirname "$0")/../.."
export HRP_SITE="$PWD/Tests/scenarios/site_white"
export SKIP_KILL=1
export SCORE_LOGDIR=build/test-logs/white_score
ROBOT_ID=$(( ${ROBOT_ID:-9100} + 400 )) exec bash Tests/scenarios/score_test.sh "$@"
