#!/usr/bin/env bash
# Turning on the spot in the sim's lockstep (motion process alone), logged tick by tick and plotted
# (each hip yaw's command against its measured angle, the feet's yaw in the world and their loads):
#   Tools/tune/turn_trace.sh [VA] [SECONDS] [OUTDIR]      e.g. turn_trace.sh 2.2 10
# VA: rad/s commanded (default 2.0); WALK_PARAMS as for the scenarios (e.g. 'velLimitA=-2.7,2.7');
# writes OUTDIR/turn.csv and OUTDIR/turn.png (default build/test-logs/turn) and prints the figures.
set -u
source "$(dirname "$0")/../../Tests/motion/kick_sim.sh"   # the sim in lockstep, shared with the walk-kick test
out=${3:-$HRP_ROOT/build/test-logs/turn}
mkdir -p "$out"
kick_sim_run "${ROBOT_ID:-9296}" "$out/main.log" \
  timeout 900 ./run_repl Tools/tune/turn_trace.lua "$out/turn.csv" "${1:-2.0}" "${2:-10}"
rc=$?
[ $rc -eq 0 ] && python3 Tools/plot/plot_turn.py "$out/turn.csv" "$out/turn.png" "turning ${1:-2.0} rad/s commanded"
exit $rc
