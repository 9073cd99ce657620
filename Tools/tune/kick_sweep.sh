#!/usr/bin/env bash
# Kicks over ball placements in one sim in lockstep (the motion process alone), figures per kick:
#   [SIM_SEED=N] Tools/tune/kick_sweep.sh [SIDES] [GAPS] [LATERALS]   (see kick_sweep.lua)
# e.g. Tools/tune/kick_sweep.sh left,right 0.08,0.1,0.12 -0.03,0,0.03
set -u
source "$(dirname "$0")/../../Tests/motion/kick_sim.sh"   # the sim in lockstep, shared with the walk-kick test
out=$KICK_LOGS
kick_sim_run "${ROBOT_ID:-9291}" "$out/main_sweep.log" \
  timeout 1200 ./run_repl Tools/tune/kick_sweep.lua "${1:-left,right}" "${2:-0.1}" "${3:-0}"
