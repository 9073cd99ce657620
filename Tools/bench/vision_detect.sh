#!/usr/bin/env bash
# The whole vision pipeline's frames per second with the new detectors (Tools/bench/vision_detect.lua)
# on 40 frames the sim renders with the white ball (seed 500: neither a test's nor training's).
#   Tools/bench/vision_detect.sh [SECONDS]
set -eu
cd "$(dirname "$0")/../.."
source Run/env.sh
F="$(mktemp /tmp/vision_detect.XXXXXX)"
trap 'rm -f "$F"' EXIT
build/bin/sim_ball_frames --out "$F" --count 40 --seed 500 --others 3 --ball white
luajit Tools/bench/vision_detect.lua "$F" "${1:-2}"
