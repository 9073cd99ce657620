#!/usr/bin/env bash
# The OP3 walks over a 5 degree ramp (up, a platform, down) and a 1 cm step (a board: up, 0.8 m,
# down) in the sim (lockstep) with the walk's IMU feedback on: no fall (off: reported as a figure).
# The boxes come into the world through a site overlay (the sim reads `objects` from its config:
# Config/platforms/Sim/sim.lua), written from Tests/motion/terrain.lua.
# Tests/motion/terrain_scenario.lua prints TAP. On the step a front foot lands half on the board's
# edge and tilts toe-up with the stiff body: the walk's tilt feedback (feedback.tilt, the IMU's
# angle on the ankles) rights the leg over it; without it the OP3 tips backwards every time. It is
# off in the OP3's config for now, so the step layout runs with TILT_PARAMS (feedback.tilt=0.5,1.0)
# unless WALK_PARAMS is given.
# `flat`: the same walk without objects.
#   [ROBOT=name] [TERRAIN_SPEED=m/s] [WALK_PARAMS=...] [SIM_SEED=n] [TERRAIN_MODES="fb nofb"] \
#     [TERRAIN_TRACE=f.csv] Tests/motion/terrain_test.sh [LAYOUT...]   (default: ramp step)
# (TERRAIN_TRACE: the last walk tick by tick; Tools/plot/plot_terrain.py plots it)
set -u
cd "$(dirname "$0")/../.."
source Run/env.sh
source Tests/tap_lib.sh
LOGDIR="$HRP_ROOT/build/test-logs/motion"
mkdir -p "$LOGDIR"
BASE_ID=$(( ${ROBOT_ID:-9200} + 70 ))
LAYOUTS=("$@")
[ ${#LAYOUTS[@]} -eq 0 ] && LAYOUTS=(ramp step)
n=0; k=0; failed=0
for layout in "${LAYOUTS[@]}"; do
  n=$((n + 1))
  id=$((BASE_ID + n))
  site="$HRP_ROOT/build/terrain-site-$layout"
  rm -rf "$site"; mkdir -p "$site"
  cp Config/site/*.lua "$site/"
  luajit Tests/motion/terrain.lua sim "$layout" >"$site/sim.lua" || { echo "not ok $((k + 1)) - terrain $layout: no layout"; exit 1; }
  params=${WALK_PARAMS-}
  [ "$layout" = step ] && [ -z "${WALK_PARAMS+x}" ] && params=${TILT_PARAMS:-feedback.tilt=0.5,1.0}
  # shellcheck disable=SC2086
  WALK_PARAMS=$params HRP_SITE=$site SCENARIO_DCM_ARGS="--seed ${SIM_SEED:-1}" \
    lockstep_scenario "$id" "terrain_$layout" Tests/motion/terrain_scenario.lua "$layout" ${TERRAIN_MODES:-}
done
[ $failed -eq 0 ]
