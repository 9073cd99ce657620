#!/usr/bin/env bash
# Benchmark: what the sim camera's realism (sim.lua camera.realism; Platforms/Sim/effects.h) costs per
# frame against the clean camera, on the same seeded scenes (4 robots, the ball, the head turning up
# to 4 rad/s during the exposure), 640x480, one thread: CPU time of the rendering thread (other load
# on the machine matters less than for the wall clock). Then the parts, by switching them off through
# a site folder: the motion blur (exposure 0), the light (no gradient, no shadows), the lens
# (no distortion). Prints figures; never fails on time.
#   Tools/bench/camera_realism.sh [SCENES]      (default 40)
set -u
cd "$(dirname "$0")/../.."
source Run/env.sh
N=${1:-40}
DIR="$HRP_ROOT/build/bench-camera"
mkdir -p "$DIR/noblur" "$DIR/nolight" "$DIR/nolens"
echo 'return { camera = { exposure = 0 } }' >"$DIR/noblur/sim.lua"
echo 'return { camera = { exposure = 0, light_gradient = 0, shadow_robot = 0, shadow_ball = 0 } }' >"$DIR/nolight/sim.lua"
cp "$DIR/nolight/sim.lua" "$DIR/nolens/sim.lua"
echo 'return { distortion = { k1 = 0, k2 = 0 } }' >"$DIR/nolens/camera.lua"
echo "machine: $(nproc) cores, load average $(cut -d' ' -f1-3 /proc/loadavg)"
run() {
  local label=$1 site=$2
  printf '%-44s ' "$label:"
  HRP_SITE=$site build/bin/sim_camera_frames --scenes "$N" --bench "${@:3}" | sed 's/^camera 640x480, //'
}
run "all effects, orange ball" "" --ball orange
run "all effects, white ball" "" --ball white
run "no motion blur" "$DIR/noblur"
run "no motion blur, flat light" "$DIR/nolight"
run "no blur, flat light, no lens distortion" "$DIR/nolens"
