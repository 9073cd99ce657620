#!/usr/bin/env bash
# The DARwIn-OP scores (Tests/scenarios/score_test.sh with ROBOT=darwin): the same Player/ code,
# only its config (Config/robots/darwin): from 10 seeded own-half starts, in the sim's lockstep.
# The goal is >= 9 of 10 within 120 s; it scores 9 of seeds 1-10 and 10 of seeds 11-20 (median 91 s
# and 77 s; the miss: a ball pushed against a goal post after its pose estimate drifted ~1 m sideways
# on the way). Runs of several
# processes are not bit-repeatable, so this gate of `make test` asks for >= 8 of 10 and keeps the
# CI from failing on one unlucky run; `make bench` (darwin_score) measures against the goal's 9.
# (The vision-kill check runs for the OP3 only.)
cd "$(dirname "$0")/../.."
ROBOT=darwin SKIP_KILL=1 SCORE_NEED=${SCORE_NEED:-8} SCORE_LOGDIR=build/test-logs/scenarios/darwin \
  ROBOT_ID=$(( ${ROBOT_ID:-9100} + 200 )) exec bash Tests/scenarios/score_test.sh "$@"
