#!/usr/bin/env bash
# The white and the orange ball, and other robots, over seeded frames the sim renders
# (build/bin/sim_ball_frames; seeds 11 and 12 here, training uses 1001 and up: Run/ball_train/train.sh),
# scored by Tests/vision/ball_frames.lua against the renderer's truth. TAP; prints every figure.
#   FRAMES=N (default 400)  DRAW=DIR: PNGs of the misses and false detections (DRAW_FRAMES=,1,2,: those frames too)
set -u
cd "$(dirname "$0")/../.."
source Run/env.sh
N="${FRAMES:-400}"
F="$(mktemp /tmp/ball_frames.XXXXXX)"
OUT="$(mktemp /tmp/ball_frames_out.XXXXXX)"
trap 'rm -f "$F" "$OUT"' EXIT
fail=0
# the goals gated are the ones met (the others print); robots (recall goal 90%) only print
build/bin/sim_ball_frames --out "$F" --count "$N" --seed 11 --others 3 --ball white || exit 1
luajit Tests/vision/ball_frames.lua "$F" white "${GATE_WHITE-recall,false,range,bearing}" >>"$OUT" || fail=1
build/bin/sim_ball_frames --out "$F" --count "$((N / 2))" --seed 12 --others 3 --ball orange || exit 1
luajit Tests/vision/ball_frames.lua "$F" orange "${GATE_ORANGE-recall,false,range,bearing}" >>"$OUT" || fail=1
# one TAP stream: the two runs' results numbered on, one plan
awk '/^(not )?ok [0-9]+/ { n++; sub(/^ok [0-9]+/, "ok " n); sub(/^not ok [0-9]+/, "not ok " n); print; next }
     /^1\.\.[0-9]+$/ { next } { print } END { print "1.." n }' "$OUT"
exit $fail
