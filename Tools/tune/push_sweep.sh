#!/usr/bin/env bash
# The largest push survived at each moment of the gait cycle, configurations side by side in one
# sim run (lockstep, motion process alone; Tools/tune/push_sweep.lua):
#   Tools/tune/push_sweep.sh DIR PHASES FORCES [LABEL=PARAMS]...
#   e.g. SIM_SEED=2 push_sweep.sh side 8 10,12,14,16,18,20 before='stepAdjust.gain=0' after=
# SIM_SEED: the sim's seed (its sensor noise); the figures' lines are "pushsweep ..." (N s).
set -u
source "$(dirname "$0")/../../Tests/motion/kick_sim.sh"   # the sim in lockstep, shared with the walk-kick test
log=$HRP_ROOT/build/test-logs/push
mkdir -p "$log"
kick_sim_run "${ROBOT_ID:-9296}" "$log/sweep_main.log" \
  timeout 3000 ./run_repl Tools/tune/push_sweep.lua "$@"
