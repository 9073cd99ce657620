#!/usr/bin/env bash
# tier: check (make check runs it: a few seconds)
# Tools/lut: a table from the config's colour boxes, a table trained from a labelled example
# image (written here as PPM: orange, green, white and blue patches with noise, and a mask painting
# the first three in their display colours), a rendered label PNG, and a corrupt table refused. TAP.
set -u
cd "$(dirname "$0")/../.."
source Run/env.sh
TOOL=build/bin/lut_tool
D=$(mktemp -d)
trap 'rm -rf "$D"' EXIT
n=0; fail=0
tap() { n=$((n + 1)); if [ "$1" = ok ]; then echo "ok $n - $2"; else echo "not ok $n - $2"; fail=1; fi; }

# classify LUT Y U V -> label (through Lib/imageproc.lua)
classify() {
  luajit -e "local ip = require('imageproc'); local lut = assert(ip.load_lut('$1'));
             io.write(ip.classify(lut, $2, $3, $4))"
}

$TOOL colors -o "$D/colors.lut" >"$D/out" 2>&1 && tap ok "colors: table from the vision config (Config/common/vision.lua)" \
  || { tap fail "colors failed: $(cat "$D/out")"; }
[ "$(classify "$D/colors.lut" 147 45 205)" = 1 ] && [ "$(classify "$D/colors.lut" 99 95 86)" = 8 ] \
  && [ "$(classify "$D/colors.lut" 240 128 128)" = 16 ] && [ "$(classify "$D/colors.lut" 80 200 100)" = 4 ] \
  && [ "$(classify "$D/colors.lut" 200 20 150)" = 0 ] \
  && tap ok "box table: orange 1, green 8, white 16, blue (a jersey) 4, yellow 0" || tap fail "box table labels wrong"

# example image: 4 vertical bands (RGB) with noise; the mask paints bands 1-3 in display colours
python3 - "$D" <<'PY'
import sys, random
d = sys.argv[1]
W, H = 160, 120
bands = [(240, 110, 20), (40, 140, 40), (235, 235, 235), (30, 60, 220)]
disp = [(255, 128, 0), (0, 160, 0), (255, 255, 255), None]
random.seed(3)
img, mask = bytearray(), bytearray()
for y in range(H):
    for x in range(W):
        k = x * 4 // W
        img += bytes(max(0, min(255, c + random.randint(-6, 6))) for c in bands[k])
        mask += bytes(disp[k] if disp[k] and 2 < y < H - 3 else (0, 0, 0))
for name, data in (('img.ppm', img), ('mask.ppm', mask)):
    with open(f'{d}/{name}', 'wb') as f:
        f.write(b'P6\n%d %d\n255\n' % (W, H) + bytes(data))
PY
$TOOL train --grow 1 -o "$D/trained.lut" "$D/img.ppm" "$D/mask.ppm" >"$D/out" 2>&1 \
  && tap ok "train: $(head -1 "$D/out")" || tap fail "train failed: $(cat "$D/out")"
# BT.601 of the band colours: orange (240,110,20) -> Y 139 U 61 V 200; green (40,140,40) -> 99 95 86;
# white 235 -> 235 128 128; blue (30,60,220) -> 69 213 100
[ "$(classify "$D/trained.lut" 139 61 200)" = 1 ] && [ "$(classify "$D/trained.lut" 99 95 86)" = 8 ] \
  && [ "$(classify "$D/trained.lut" 235 128 128)" = 16 ] && tap ok "trained table labels the examples" \
  || tap fail "trained table labels wrong"
[ "$(classify "$D/trained.lut" 69 213 100)" = 0 ] && [ "$(classify "$D/trained.lut" 180 30 30)" = 0 ] \
  && tap ok "unlabelled colours stay unlabelled" || tap fail "unlabelled colour got a label"

$TOOL render --lut "$D/trained.lut" -o "$D/labels.png" "$D/img.ppm" >"$D/out" 2>&1
rc=$?
orange=$(awk '$1=="orange"{print $2}' "$D/out"); blue_free=$(awk '$1=="white"{print $2}' "$D/out")
[ $rc -eq 0 ] && [ -s "$D/labels.png" ] && [ "$(head -c 4 "$D/labels.png" | tail -c 3)" = PNG ] \
  && tap ok "render wrote a PNG" || tap fail "render failed: $(cat "$D/out")"
# 80x60 labels, the orange band is a quarter of it (20 columns x 60 rows)
[ "${orange:-0}" -ge 1100 ] && [ "${orange:-0}" -le 1200 ] && [ "${blue_free:-0}" -ge 1100 ] \
  && tap ok "render counts: orange $orange, white $blue_free of 4800" \
  || tap fail "render counts wrong: $(cat "$D/out")"

head -c 1000 "$D/trained.lut" >"$D/bad.lut"
$TOOL render --lut "$D/bad.lut" -o "$D/x.png" "$D/img.ppm" >"$D/out" 2>&1
[ $? -ne 0 ] && grep -q "$D/bad.lut" "$D/out" && tap ok "a truncated table is refused, file named" \
  || tap fail "bad table not refused: $(cat "$D/out")"
echo "1..$n"
exit $fail
