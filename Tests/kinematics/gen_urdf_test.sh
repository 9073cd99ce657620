#!/usr/bin/env bash
# tier: check (make check runs it: a few seconds)
# Tools/urdf/gen_urdf.py (TAP), on the one reference file the repository holds (the waistbot test body's;
# the real robots' references live outside the repository): regenerating gives the committed
# URDF byte for byte; sections the generator does not use (a Hubo-style LIMITS, ACTUATORS, SENSORS)
# are skipped, not fatal; a reference without CAMERA fails naming the frame that needs it; robot.lua's
# added_masses and collision_skip (the Hubo2+'s) do what they say.
set -u
cd "$(dirname "$0")/../.."
source Run/env.sh
TMP="$HRP_ROOT/build/tmp/gen_urdf_test"
rm -rf "$TMP" && mkdir -p "$TMP"
REF=Config/robots/waistbot/waistbot_reference.txt
n=0; fails=0
check() { n=$((n + 1)); if [ "$1" = 0 ]; then echo "ok $n - $2"; else fails=$((fails + 1)); echo "not ok $n - $2"; fi; }

python3 Tools/urdf/gen_urdf.py waistbot "$REF" --out "$TMP/a.urdf" >"$TMP/a.log" 2>&1
cmp -s "$TMP/a.urdf" Config/robots/waistbot/waistbot.urdf
check $? "regenerating waistbot.urdf from its reference gives the committed file"

{ cat "$REF"; printf 'LIMITS\n# joint lo hi\nWST -3.14 3.14  1 6\nACTUATORS\nWST 0 EJMC3 0x23\nSENSORS\nimu torso 0 0 1\n'; } >"$TMP/extra.txt"
python3 Tools/urdf/gen_urdf.py waistbot "$TMP/extra.txt" --out "$TMP/b.urdf" >"$TMP/b.log" 2>&1
rc=$?
[ $rc = 0 ] && grep -q 'section LIMITS not used' "$TMP/b.log" && grep -q 'section SENSORS not used' "$TMP/b.log"
check $? "unknown sections (LIMITS, ACTUATORS, SENSORS) are skipped and said so"
sed 1,2d "$TMP/b.urdf" | cmp -s - <(sed 1,2d "$TMP/a.urdf")
check $? "... and change nothing else"

sed '/^CAMERA/,$d' "$REF" >"$TMP/nocam.txt"
python3 Tools/urdf/gen_urdf.py waistbot "$TMP/nocam.txt" --out "$TMP/c.urdf" >"$TMP/c.log" 2>&1
rc=$?
[ $rc != 0 ] && grep -q 'frames.camera_link' "$TMP/c.log" && [ ! -e "$TMP/c.urdf" ]
check $? "no CAMERA and no xyz for camera_link: fails naming the frame ($(tail -1 "$TMP/c.log"))"

sed 's/^l_wrist_link l_el_link 0.1 /l_wrist_link l_el_link 0.1 0.2 /' "$REF" >"$TMP/bad.txt"
python3 Tools/urdf/gen_urdf.py waistbot "$TMP/bad.txt" --out "$TMP/d.urdf" >"$TMP/d.log" 2>&1
rc=$?
[ $rc != 0 ] && grep -q 'bad.txt:[0-9]*: body line needs 19 fields' "$TMP/d.log"
check $? "a malformed body line: fails naming the file and the line ($(tail -1 "$TMP/d.log"))"

# robot.lua's added_masses (merged by the parallel-axis rule) and collision_skip, on made-up data
python3 - >"$TMP/e.log" 2>&1 <<'PY'
import sys
sys.path.insert(0, 'Tools/urdf')
import gen_urdf as g
# a 1 kg point-like body at the origin plus a 1 kg uniform 0.1 m cube centred 0.2 m up
b = dict(name='a', mass=1.0, com=[0.0, 0.0, 0.0], inertia=[0.0] * 6)
g.add_mass(b, 1.0, [0.0, 0.0, 0.2], [0.1, 0.1, 0.1])
cube = 1.0 * (0.01 + 0.01) / 12
want = dict(mass=2.0, com=[0.0, 0.0, 0.1], inertia=[2 * 0.01 + cube, 2 * 0.01 + cube, cube, 0, 0, 0])
assert abs(b['mass'] - 2.0) < 1e-12, b
assert all(abs(x - y) < 1e-12 for x, y in zip(b['com'], want['com'])), b
assert all(abs(x - y) < 1e-12 for x, y in zip(b['inertia'], want['inertia'])), b
boxes = [dict(kind='sole_box'), dict(kind='sole_outline'), dict(kind='mesh_aabb')]
g.apply_robot_data({'collision_skip': ['sole_outline']}, 'robot.lua', [b], boxes)
assert [x['kind'] for x in boxes] == ['sole_box', 'mesh_aabb'], boxes
try:
    g.apply_robot_data({'added_masses': [{'link': 'nope', 'mass': 1, 'com': [0, 0, 0], 'size': [1, 1, 1]}]},
                       'robot.lua', [b], boxes)
except SystemExit:
    print('refused')
PY
rc=$?
[ $rc = 0 ] && grep -q "added_masses\[1\]: link 'nope' is not a body" "$TMP/e.log" && grep -q refused "$TMP/e.log"
check $? "added_masses merges by the parallel-axis rule, collision_skip drops a kind, an unknown link fails naming it"

echo "1..$n"
[ "$fails" = 0 ]
