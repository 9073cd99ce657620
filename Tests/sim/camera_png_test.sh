#!/usr/bin/env bash
# tier: check (make check runs it: a few seconds)
# The camera PNG tool (TAP): renders a head-camera frame with the ball and a goal in view to a PNG;
# checks the file and that the ball's orange shows up around its projected centre.
# (The pixel-accurate projection check is build/tests/sim_camera.)
set -u
cd "$(dirname "$0")/../.."
out=$(mktemp --suffix=.png)
trap 'rm -f "$out"' EXIT
line=$(build/bin/sim_render_png --out "$out" --robot 1.8 0.3 0 --ball 2.8 -0.1 --head 0 -0.25 --other 3.0 0.6 3.14)
rc=$?
echo "# $line"
n=0; fails=0
res() { n=$((n + 1)); if [ "$1" = 0 ]; then echo "ok $n - $2"; else fails=$((fails + 1)); echo "not ok $n - $2"; fi; }
res $rc "sim_render_png renders a frame"
uv=$(echo "$line" | sed -n 's/.*projects to (\([0-9.]*\), \([0-9.]*\)).*/\1 \2/p')
python3 - "$out" $uv <<'PY'
import struct, sys, zlib
path, u, v = sys.argv[1], float(sys.argv[2]), float(sys.argv[3])
data = open(path, 'rb').read()
assert data[:8] == b'\x89PNG\r\n\x1a\n', 'not a PNG'
w, h = struct.unpack('>II', data[16:24])
assert (w, h) == (640, 480), (w, h)
# decode (8-bit RGB, filters 0-4) to look at the pixel under the ball's projected centre
idat, pos = b'', 8
while pos < len(data):
    n, = struct.unpack('>I', data[pos:pos + 4]); t = data[pos + 4:pos + 8]
    if t == b'IDAT': idat += data[pos + 8:pos + 8 + n]
    pos += 12 + n
raw = zlib.decompress(idat); stride = w * 3; rows = []; prev = bytearray(stride)
for y in range(h):
    f = raw[y * (stride + 1)]; line = bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
    for i in range(stride):
        a = line[i - 3] if i >= 3 else 0; b = prev[i]; c = prev[i - 3] if i >= 3 else 0
        if f == 1: line[i] = (line[i] + a) & 255
        elif f == 2: line[i] = (line[i] + b) & 255
        elif f == 3: line[i] = (line[i] + (a + b) // 2) & 255
        elif f == 4:
            p = a + b - c; pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
            line[i] = (line[i] + (a if pa <= pb and pa <= pc else (b if pb <= pc else c))) & 255
    rows.append(line); prev = line
r, g, b = rows[int(round(v))][3 * int(round(u)):3 * int(round(u)) + 3]
print('# pixel at the ball centre (%.0f, %.0f): rgb %d %d %d' % (u, v, r, g, b))
assert r > 150 and g < 120 and b < 80, 'not orange'
PY
res $? "the PNG is 640x480 and the ball is orange at its projected centre"
echo "1..$n"
[ $fails -eq 0 ]
