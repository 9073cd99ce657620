#!/usr/bin/env bash
# Tunes a walk kick in the sim (lockstep, the motion process alone; Tests/motion/walk_kick_tune.lua):
#   Tests/motion/walk_kick_tune.sh [forward|side] [ITERS] [POP] [OUT.lua]
set -u
source "$(dirname "$0")/kick_sim.sh"
kick_sim_run "${ROBOT_ID:-9296}" "$KICK_LOGS/main_walk_kick_tune.log" \
  timeout 7200 ./run_repl Tests/motion/walk_kick_tune.lua "${1:-forward}" "${2:-6}" "${3:-10}" \
  "${4:-$KICK_LOGS/walk_kick_${1:-forward}.lua}"
