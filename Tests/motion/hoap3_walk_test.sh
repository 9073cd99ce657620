#!/usr/bin/env bash
# The HOAP-3's walking scenarios (Tests/motion/sim_walk_test.sh with ROBOT=hoap3): the same Player/
# code as the other bodies, only its config (Config/robots/hoap3): standing 60 s, forward >= 0.12 m/s
# for 30 s, sideways and backwards 0.04 m/s, turning on the spot 0.4 rad/s (the targets:
# Tests/motion/targets.lua), 60 s of random commands with three seeds, the head taken from the REPL
# while walking. Not here: 'push' and 'kick' (no stand-up or kick motions for this body yet: it has
# a fall policy).
cd "$(dirname "$0")/../.."
[ $# -eq 0 ] && set -- stand forward sideways turn backward random "random 60 2" "random 60 3" head
ROBOT=hoap3 ROBOT_ID=$(( ${ROBOT_ID:-9200} + 80 )) exec bash Tests/motion/sim_walk_test.sh "$@"
