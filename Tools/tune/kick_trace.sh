#!/usr/bin/env bash
# A kick logged tick by tick in the sim's lockstep (motion process alone), plotted to PNG:
#   [SIM_SEED=N] Tools/tune/kick_trace.sh [left|right] [GAP] [OUTDIR]
# writes OUTDIR/kick_SIDE.csv and OUTDIR/kick_SIDE.png (default OUTDIR build/test-logs/kick) and
# prints the figures (ball distance, toe speed at contact, peak ball speed, where the ball met the foot).
set -u
source "$(dirname "$0")/../../Tests/motion/kick_sim.sh"   # the sim in lockstep, shared with the walk-kick test
side=${1:-left}; gap=${2:-0.1}
out=${3:-$KICK_LOGS}
mkdir -p "$out"
kick_sim_run "${ROBOT_ID:-9290}" "$out/main_$side.log" \
  timeout 300 ./run_repl Tools/tune/kick_trace.lua "$side" "$out/kick_$side.csv" "$gap"
rc=$?
[ $rc -eq 0 ] && python3 Tools/plot/plot_kick.py "$out/kick_$side.csv" "$out/kick_$side.png" "kick $side gap $gap"
exit $rc
