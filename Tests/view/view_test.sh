#!/usr/bin/env bash
# The live view in headless Chromium (TAP, Tests/view/view_check.py): one robot plays in the sim in
# real time (./run_main --sim, as make sim), ./run_view serves it, Debian's chromium (driven by
# Playwright, no downloaded browser) shows it; the truth marker's pixel is where the sim's truth says,
# the camera panel shows the orange ball, and the latency from a shm write to the page is measured.
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
