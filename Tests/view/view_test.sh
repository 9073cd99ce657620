#!/usr/bin/env bash
# The live view in headless Chromium (TAP, Tests/view/view_check.py): one robot plays in the sim in
# real time (./run_main --sim, as make sim), ./run_view serves it, Debian's chromium (driven by
# Playwright, no downloaded browser) shows it; the truth marker's pixel is where the sim's truth says,
# the camera panel shows the orange ball, and the latency from a shm write to the page is measured.
# Then the same robot with its motion process alone, in the whole-body state (Tests/view/wbc_probe.lua):
# the whole-body panel shows its tasks as the wbc block holds them (view_check.py --wbc).
set -u
cd "$(dirname "$0")/../.."
source Run/env.sh
dir=$(mktemp -d)
cleanup() {
  for p in ${probe:-} ${srv:-} ${robot:-}; do kill -TERM "$p" 2>/dev/null; done
  for p in ${probe:-} ${srv:-} ${robot:-}; do wait "$p" 2>/dev/null; done
  Tools/shm/shm remove >/dev/null 2>&1
  rm -rf "$dir"
}
trap cleanup EXIT
Tools/shm/shm remove >/dev/null 2>&1
./run_main --sim --quiet > "$dir/robot.out" 2>&1 &
robot=$!
./run_view --port 0 > "$dir/view.out" 2>&1 &
srv=$!
url=""
for _ in $(seq 50); do
  url=$(grep -o 'http://[^ ]*' "$dir/view.out" 2>/dev/null | head -1)
  [ -n "$url" ] && break
  sleep 0.1
done
if [ -z "$url" ]; then
  echo "not ok 1 - ./run_view printed its URL # $(cat "$dir/view.out")"
  echo "1..1"
  exit 1
fi
echo "# view at $url"
luajit Tests/view/probe.lua 40 0.023 &
probe=$!
python3 Tests/view/view_check.py --url "$url" --server-pid "$srv" --out "build/test-logs/view.png"
rc=$?
kill -TERM "$robot" "$probe" 2>/dev/null
wait "$robot" "$probe" 2>/dev/null
Tools/shm/shm remove >/dev/null 2>&1
./run_main --sim --quiet --no-restart --dcm-arg --no-camera motion > "$dir/robot_wbc.out" 2>&1 &
robot=$!
for _ in $(seq 200); do grep -q 'motion started' "$dir/robot_wbc.out" 2>/dev/null && break; sleep 0.1; done
if ! timeout 60 ./run_repl Tests/view/wbc_probe.lua > "$dir/probe_wbc.out" 2>&1; then
  echo "not ok 6 - the robot runs the wbc state # $(tail -3 "$dir/probe_wbc.out" | tr '\n' ' ')"
  exit 1
fi
sed 's/^/# /' "$dir/probe_wbc.out"
python3 Tests/view/view_check.py --url "$url" --wbc --first 6 --out "build/test-logs/view_wbc.png" || rc=1
exit $rc
