#!/usr/bin/env bash
# The DARwIn-OP's walking scenarios (Tests/motion/sim_walk_test.sh with ROBOT=darwin): the same
# Player/ code, only its config (Config/robots/darwin): standing 60 s, forward >= 0.20 m/s for 30 s,
# sideways, backwards, turning, 60 s of random commands, kicks with both feet (>= 1.2 m), the head
# taken from the REPL while walking, pushed over forwards and backwards (it stands up by itself and
# walks again).
cd "$(dirname "$0")/../.."
[ $# -eq 0 ] && set -- stand forward sideways turn backward random push kick head
ROBOT=darwin ROBOT_ID=$(( ${ROBOT_ID:-9200} + 40 )) exec bash Tests/motion/sim_walk_test.sh "$@"
