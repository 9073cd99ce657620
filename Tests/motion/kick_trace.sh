#!/usr/bin/env bash
# A kick logged tick by tick in the sim's lockstep (motion process alone), plotted to PNG:
#   Tests/motion/kick_trace.sh [left|right] [GAP] [OUTDIR]
# writes OUTDIR/kick_SIDE.csv and OUTDIR/kick_SIDE.png (default OUTDIR build/test-logs/kick) and
# prints the figures (ball distance, toe speed at contact, peak ball speed).
set -u
cd "$(dirname "$0")/../.."
source Run/env.sh
side=${1:-left}; gap=${2:-0.1}
out=${3:-$HRP_ROOT/build/test-logs/kick}
mkdir -p "$out"
id=${ROBOT_ID:-9290}
ROBOT_ID=$id ./run_main --sim --quiet --no-restart --dcm-arg --lockstep --dcm-arg --seed --dcm-arg 1 \
  --dcm-arg --no-camera motion >"$out/main_$side.log" 2>&1 &
main_pid=$!
for _ in $(seq 200); do
  grep -q 'motion started' "$out/main_$side.log" 2>/dev/null && break
  sleep 0.1
done
ROBOT_ID=$id timeout 300 ./run_repl Tests/motion/kick_trace.lua "$side" "$out/kick_$side.csv" "$gap"
rc=$?
kill -TERM "$main_pid" 2>/dev/null
wait "$main_pid" 2>/dev/null
Run/shm --robot "$id" remove >/dev/null 2>&1
[ $rc -eq 0 ] && python3 Tests/motion/plot_kick.py "$out/kick_$side.csv" "$out/kick_$side.png" "kick $side gap $gap"
exit $rc
