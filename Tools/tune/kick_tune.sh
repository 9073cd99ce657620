#!/usr/bin/env bash
# Tunes the kick in the sim (lockstep, the motion process alone): see kick_tune.lua.
#   [SIM_SEED=N] [ROBOT_ID=N] Tools/tune/kick_tune.sh GENERATIONS SEED OUT.lua [SPREAD]
set -u
source "$(dirname "$0")/../../Tests/motion/kick_sim.sh"   # the sim in lockstep, shared with the walk-kick test
out=$KICK_LOGS
kick_sim_run "${ROBOT_ID:-9292}" "$out/main_tune_${2:-1}.log" \
  ./run_repl Tools/tune/kick_tune.lua "${1:-30}" "${2:-1}" "${3:-$out/kick_best_${2:-1}.lua}" "${4:-1}"
