#!/usr/bin/env bash
# The HOAP-3's walking scenarios (Tests/motion/sim_walk_test.sh with ROBOT=hoap3): the same Player/
# code as the other bodies, only its config (Config/robots/hoap3): standing 60 s, forward >= 0.08 m/s
# for 30 s, sideways 0.03 m/s, backwards 0.04 m/s, turning on the spot 0.3 rad/s (the targets:
# Tests/motion/targets.lua), 60 s of random commands with three seeds. Not here: 'push' and 'kick'
# (no stand-up or kick motions for this body yet: it has a fall policy), 'head' (the scenario
# drives the OP-class head).
cd "$(dirname "$0")/../.."
[ $# -eq 0 ] && set -- stand forward sideways turn backward random "random 60 2" "random 60 3"
ROBOT=hoap3 ROBOT_ID=$(( ${ROBOT_ID:-9200} + 80 )) exec bash Tests/motion/sim_walk_test.sh "$@"
