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
LOGDIR="$HRP_ROOT/build/test-logs/motion"
mkdir -p "$LOGDIR"
failed=0; k=0
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
Tools/shm/shm --robot "$id" remove >/dev/null 2>&1   # stale segments of an earlier run
HRP_SITE=$site ROBOT=hoap3 ROBOT_ID=$id ./run_main --sim --quiet --no-restart --dcm-arg --lockstep-wait \
  --dcm-arg 2 --dcm-arg --no-camera motion >"$LOGDIR/main_hoap3_touch.log" 2>&1 &
main_pid=$!
for _ in $(seq 200); do grep -q 'motion started' "$LOGDIR/main_hoap3_touch.log" 2>/dev/null && break; sleep 0.1; done
HRP_SITE=$site ROBOT=hoap3 ROBOT_ID=$id timeout 300 ./run_repl Tests/motion/hoap3_touch.lua "$wall_x" \
  >"$LOGDIR/hoap3_touch.log" 2>&1
rc=$?
kill -TERM "$main_pid" 2>/dev/null
wait "$main_pid" 2>/dev/null
Tools/shm/shm --robot "$id" remove >/dev/null 2>&1
tap_merge "$LOGDIR/hoap3_touch.log" hoap3_touch "$rc"
echo "1..$k"
[ $failed -eq 0 ]
