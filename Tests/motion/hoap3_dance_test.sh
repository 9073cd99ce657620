#!/usr/bin/env bash
# tier: test (make test runs two rounds, a turn between them: about 40 s; the whole 3-minute dance:
# HOAP3_DANCE_ROUNDS=0)
# The HOAP-3's dance (issue: the HOAP-3 study's 3-minute dance) in the sim (lockstep): its routine
# (Config/robots/hoap3/routines/dance.lua: whole-body moves standing, quarter turns on the spot)
# played by Tests/motion/hoap3_dance.lua, which prints the figures (the measured ZMP's smallest
# margin inside the support polygon by kind of step) and TAP.
#   [HOAP3_DANCE_ROUNDS=n] Tests/motion/hoap3_dance_test.sh   (n = 0: the routine's own five rounds)
set -u
cd "$(dirname "$0")/../.."
source Run/env.sh
source Tests/tap_lib.sh
scenario_logs motion
rounds=${HOAP3_DANCE_ROUNDS:-2}
[ "$rounds" = 0 ] && rounds=
ROBOT=hoap3 lockstep_scenario $(( ${ROBOT_ID:-9200} + 96 )) hoap3_dance Tests/motion/hoap3_dance.lua $rounds
echo "1..$k"
[ $failed -eq 0 ]
