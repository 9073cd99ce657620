#!/usr/bin/env bash
# Sideways pushes on the walking robot in the sim's lockstep (motion process alone), the last one
# logged tick by tick and plotted (truth, the walk's COM and feet, the capture point error):
#   Tools/tune/push_trace.sh FORCES MOMENTS [GAIN] [OUTDIR]   e.g. push_trace.sh 20 0,1,2,3 1.0
# FORCES, MOMENTS: comma lists (N for 0.1 s; k x tStep/2 into the gait cycle); GAIN: stepAdjust.gain
# (0: off); writes OUTDIR/push.csv, OUTDIR/push.png and OUTDIR/push_feet.png (the feet: plot_push_feet.py;
# default build/test-logs/push).
set -u
source "$(dirname "$0")/../../Tests/motion/kick_sim.sh"   # the sim in lockstep, shared with the walk-kick test
out=${4:-$HRP_ROOT/build/test-logs/push}
mkdir -p "$out"
kick_sim_run "${ROBOT_ID:-9295}" "$out/main.log" \
  timeout 900 ./run_repl Tools/tune/push_trace.lua "$out/push.csv" "${1:-20}" "${2:-0,1,2,3}" ${3:+"$3"}
rc=$?
title="push ${1:-20} N x 0.1 s, moment ${2:-0,1,2,3}, gain ${3:-config}"
[ $rc -eq 0 ] && python3 Tools/plot/plot_push.py "$out/push.csv" "$out/push.png" "$title" &&
  python3 Tools/plot/plot_push_feet.py "$out/push.csv" "$out/push_feet.png" "$title"
exit $rc
