#!/usr/bin/env bash
# The Hubo2+'s scenarios (Tests/motion/sim_walk_test.sh with ROBOT=hubo2plus): the same Player/ code
# as the small bodies, only its config (Config/robots/hubo2plus): standing 60 s, forward >= 0.25 m/s
# for 30 s, sideways 0.1 m/s, backwards, turning on the spot 0.5 rad/s, 60 s of random commands
# (the targets: Tests/motion/targets.lua), key poses for the arms and the waist played while
# standing, and pushes that tip it over handled by its fall policy (protective pose held, no
# stand-up: a 45 kg robot does not get up by itself). Not here: 'push' and 'kick' (stand-ups and
# football are the small bodies'), 'head' (the Hubo's head has no pan joint).
cd "$(dirname "$0")/../.."
[ $# -eq 0 ] && set -- stand forward sideways turn backward random keypose fallpolicy
ROBOT=hubo2plus ROBOT_ID=$(( ${ROBOT_ID:-9200} + 70 )) exec bash Tests/motion/sim_walk_test.sh "$@"
