#!/usr/bin/env bash
# tier: check (make check runs it: a few seconds)
# The sim camera's degraded frames (TAP): build/bin/sim_camera_frames renders seeded scenes with the
# clean and the realistic camera (sim.lua camera.realism) to PNGs; the files are there, are PNGs of
# the expected size, and a second run writes the same bytes (deterministic for a seed). Look at them:
#   build/bin/sim_camera_frames --out DIR --scenes 8 [--ball white] [--montage FILE]
set -u
cd "$(dirname "$0")/../.."
source Run/env.sh
d1=$(mktemp -d) d2=$(mktemp -d)
trap 'rm -rf "$d1" "$d2"' EXIT
n=0
res() { n=$((n + 1)); if [ "$1" = 0 ]; then echo "ok $n - $2"; else echo "not ok $n - $2"; fi; }
build/bin/sim_camera_frames --out "$d1" --scenes 3 --seed 4 --ball white --montage "$d1/montage.png" | sed 's/^/# /'
res "${PIPESTATUS[0]}" "sim_camera_frames renders 3 scenes and a montage"
build/bin/sim_camera_frames --out "$d2" --scenes 3 --seed 4 --ball white --montage "$d2/montage.png" >/dev/null
ok=0
for f in scene_00 scene_01 scene_02 montage; do
  [ -s "$d1/$f.png" ] || ok=1
done
res $ok "the scenes' PNGs and the montage are written"
python3 - "$d1/scene_00.png" "$d1/montage.png" <<'PY'
import struct, sys
for path, size in zip(sys.argv[1:], [(1280, 480), (640, 240)]):
    data = open(path, 'rb').read()
    assert data[:8] == b'\x89PNG\r\n\x1a\n', path + ': not a PNG'
    assert struct.unpack('>II', data[16:24]) == size, path + ': size %dx%d' % struct.unpack('>II', data[16:24])
PY
res $? "PNGs of clean | realistic side by side (1280x480) and the 640x240 montage"
same=0
for f in scene_00 scene_01 scene_02 montage; do cmp -s "$d1/$f.png" "$d2/$f.png" || same=1; done
res $same "a second run with the same seed writes the same bytes"
echo "1..$n"
