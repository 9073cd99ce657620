#!/usr/bin/env bash
# Trains the white-ball classifier from frames the sim renders, and writes it where the vision
# loads it (vision.ball.white.model, Config/common/ball_white.mlp). CPU, a few minutes.
#   Tools/ball_train/train.sh [OUT]        FRAMES=N per chunk (250), CHUNKS=N (40), OTHERS=K robots (3)
#   SAMPLES=FILE keeps the samples there (train.py can be rerun on them with other settings)
# Training seeds are 1000 + chunk: the tests render their scenes from seeds below 1000
# (Tests/vision/ball_frames_test.sh), so no test frame is a training frame.
set -eu
cd "$(dirname "$0")/../.."
source Run/env.sh
OUT="${1:-Config/common/ball_white.mlp}"
FRAMES="${FRAMES:-250}"
CHUNKS="${CHUNKS:-40}"
OTHERS="${OTHERS:-3}"
MARGIN=1.4
TMP="$(mktemp -d /tmp/ball_train.XXXXXX)"
trap 'rm -rf "$TMP"' EXIT
make -s -C Platforms/Sim all >/dev/null
make -s -C Modules/balldetect all >/dev/null
for c in $(seq 1 "$CHUNKS"); do
  seed=$((1000 + c))
  build/bin/sim_ball_frames --out "$TMP/frames.bin" --count "$FRAMES" --seed "$seed" --others "$OTHERS" --ball white
  BALL_MARGIN=$MARGIN luajit Tools/ball_train/samples.lua "$TMP/frames.bin" "$TMP/samples.bin" "$seed"
done
python3 Tools/ball_train/train.py "$TMP/samples.bin" "$OUT" --margin $MARGIN
if [ -n "${SAMPLES:-}" ]; then mv "$TMP/samples.bin" "$SAMPLES"; fi
