#!/usr/bin/env bash
# Benchmark (make bench: hoap3_score): the HOAP-3 scores (Tests/scenarios/score_test.sh with
# ROBOT=hoap3): the same Player/ code, only its config (Config/robots/hoap3: behavior.lua,
# camera.lua, walk.lua), from 10 seeded own-half starts in the sim's lockstep, 180 s each (it walks
# at 0.14 m/s, the OP3 at 0.38). The goal is >= 8 of 10. Not in `make test`: one run takes
# 100-145 s of robot time, minutes of wall time on a shared 2-core machine.
#   Tools/bench/hoap3_score.sh [SEEDS...]      (default: 1..10)
# Prints each seed's outcome, goals, the median time to goal, falls (it has no stand-up: a fall
# ends its play) and the walk's speeds in play; TAP. Logs and traces in
# build/test-logs/scenarios/hoap3/ (FRAME_DIR=DIR: PNGs of its eye's frames, see score_one.lua).
cd "$(dirname "$0")/../.."
[ $# -eq 0 ] && set -- 1 2 3 4 5 6 7 8 9 10
ROBOT=hoap3 SKIP_KILL=1 SCORE_LIMIT=${SCORE_LIMIT:-180} SCORE_NEED=${SCORE_NEED:-8} \
  SCORE_LOGDIR=build/test-logs/scenarios/hoap3 ROBOT_ID=$(( ${ROBOT_ID:-9100} + 220 )) \
  exec bash Tests/scenarios/score_test.sh "$@"
