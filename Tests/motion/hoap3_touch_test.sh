#!/usr/bin/env bash
# tier: check (make check runs it: about 20 s)
# The HOAP-3 touches a wall with both hands (issue: the HOAP-3 study's wall touch), in the sim
# (lockstep): a wall put in the world through a site overlay (the sim's `objects`), its face
# WALL_X in front of the robot's start; Tests/motion/hoap3_touch.lua requests the touch motion and
# prints the figures (the wrist forces, where the hands are) and TAP.
#   Tests/motion/hoap3_touch_test.sh
set -u
cd "$(dirname "$0")/../.."
source Run/env.sh
source Tests/tap_lib.sh
scenario_logs motion
id=$(( ${ROBOT_ID:-9200} + 95 ))
# the robot starts at x = -1.0 (Config/platforms/Sim/sim.lua start), at its zero pose (arms level
# forward: the hands 0.2 m ahead of the soles), then stands (the hands hang 2 cm ahead); its arms,
# straight and level, would reach 0.24 m ahead: the wall's face at 0.225 m is met on the way up
wall_x=-0.775
site="$HRP_ROOT/build/touch-site"
rm -rf "$site"; mkdir -p "$site"
cp Config/site/*.lua "$site/"
cat >"$site/sim.lua" <<LUA
return { objects = { { pos = { $wall_x + 0.05, 0, 0.5 }, size = { 0.1, 1.0, 1.0 }, rpy = { 0, 0, 0 } } } }
LUA
HRP_SITE=$site ROBOT=hoap3 lockstep_scenario "$id" hoap3_touch Tests/motion/hoap3_touch.lua "$wall_x"
echo "1..$k"
[ $failed -eq 0 ]
