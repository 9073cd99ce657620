#!/usr/bin/env bash
# Tunes the kick in the sim (lockstep, the motion process alone): see kick_tune.lua.
#   [SIM_SEED=N] [ROBOT_ID=N] Tests/motion/kick_tune.sh GENERATIONS SEED OUT.lua [SPREAD]
set -u
source "$(dirname "$0")/kick_sim.sh"
out=$KICK_LOGS
kick_sim_run "${ROBOT_ID:-9292}" "$out/main_tune_${2:-1}.log" \
  ./run_repl Tests/motion/kick_tune.lua "${1:-30}" "${2:-1}" "${3:-$out/kick_best_${2:-1}.lua}" "${4:-1}"
