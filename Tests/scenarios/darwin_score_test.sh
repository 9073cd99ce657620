#!/usr/bin/env bash
# The DARwIn-OP scores (Tests/scenarios/score_test.sh with ROBOT=darwin): the same Player/ code,
# only its config (Config/robots/darwin): from 10 seeded own-half starts, in the sim's lockstep,
# it scores within 120 s in at least 9 of 10. (The vision-kill check runs for the OP3 only.)
cd "$(dirname "$0")/../.."
ROBOT=darwin SKIP_KILL=1 SCORE_LOGDIR=build/test-logs/scenarios/darwin ROBOT_ID=$(( ${ROBOT_ID:-9100} + 200 )) \
  exec bash Tests/scenarios/score_test.sh "$@"
