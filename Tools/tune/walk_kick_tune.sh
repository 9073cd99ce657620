#!/usr/bin/env bash
# Tunes a walk kick in the sim (lockstep, the motion process alone; Tools/tune/walk_kick_tune.lua):
#   Tools/tune/walk_kick_tune.sh [forward|side] [ITERS] [POP] [OUT.lua]
set -u
source "$(dirname "$0")/../../Tests/motion/kick_sim.sh"   # the sim in lockstep, shared with the walk-kick test
kick_sim_run "${ROBOT_ID:-9296}" "$KICK_LOGS/main_walk_kick_tune.log" \
  timeout 7200 ./run_repl Tools/tune/walk_kick_tune.lua "${1:-forward}" "${2:-6}" "${3:-10}" \
  "${4:-$KICK_LOGS/walk_kick_${1:-forward}.lua}"
