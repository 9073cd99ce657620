#!/usr/bin/env bash
# Every body of Config/robots stands in the sim (TAP): Platforms/Sim's world test (joint signs
# against the URDF axes, 60 s in a bent-knee stance with each joint driven by its own actuator
# model: no fall, tracking, drift, foot forces, accelerometer) run once per body, the default
# body (op3) being covered by build/tests/sim_world itself.
set -u
cd "$(dirname "$0")/../.."
source Run/env.sh
if [ ! -x build/tests/sim_world ]; then
  echo "not ok 1 - bodies stand: build/tests/sim_world is not built"
  exit 1
fi
n=0; fails=0
for dir in Config/robots/*/; do
  body=$(basename "$dir")
  [ "$body" = op3 ] && continue
  [ -f "$dir/robot.lua" ] || continue   # a folder with only some concerns (hubo2plus's can.lua) is no body yet
  while IFS= read -r line; do
    case "$line" in
      "ok "*) n=$((n + 1)); echo "ok $n - $body: ${line#ok * - }" ;;
      "not ok "*) n=$((n + 1)); fails=$((fails + 1)); echo "not ok $n - $body: ${line#not ok * - }" ;;
      "#"*) echo "# $body: ${line#\# }" ;;
    esac
  done < <(ROBOT=$body build/tests/sim_world 2>&1)
done
echo "1..$n"
[ "$fails" -eq 0 ]
