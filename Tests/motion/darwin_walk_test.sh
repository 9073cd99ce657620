#!/usr/bin/env bash
# The DARwIn-OP's walking scenarios (Tests/motion/sim_walk_test.sh with ROBOT=darwin): the same
# Player/ code, only its config (Config/robots/darwin): standing 60 s, forward >= 0.20 m/s for 30 s,
# sideways, backwards, turning, 60 s of random commands, kicks with both feet (>= 1.2 m), the head
# taken from the REPL while walking. Not here yet: 'push' (pushed over, it must stand up by itself):
# its stand-ups succeed in about 3 of 4 falls (`make bench`: standup_darwin), and the fixed push
# backwards of the scenario is one it does not get up from.
cd "$(dirname "$0")/../.."
[ $# -eq 0 ] && set -- stand forward sideways turn backward random kick head
ROBOT=darwin ROBOT_ID=$(( ${ROBOT_ID:-9200} + 40 )) exec bash Tests/motion/sim_walk_test.sh "$@"
