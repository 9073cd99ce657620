#!/usr/bin/env bash
# Scenario (make bench; walk_kick_test.sh runs its forward part in make test): kicks out of the walk
# in the sim's lockstep (the motion process alone): the OP3 walks, a ball is put in its kick zone,
# Walk.kick asks for a forward or side kick with either foot; every kick sends the ball
# its kind's minimum (the sim's truth; WALK_KICK_MIN_FORWARD default 1.5 m, the goal, over the
# OP3's kick zone: 1.50-2.17 m on seeds 1-3; WALK_KICK_MIN_SIDE 0.4 m: the side kick's 0.44-0.67 m)
# while the robot walks on (no stop, no fall). Prints the distance per case
# (Tests/motion/walk_kick_scenario.lua).
#   Tests/motion/walk_kick_sweep.sh [SWEEPS] [FEET] [VX]     e.g. 'forward=-0.03,0.03/-0.02,0.02' left
# (default: the OP3's forward kick zone and two side-kick balls, both feet, 0.12 m/s)
# env: ROBOT_ID (default 9295), SIM_SEED, WALK_KICK_MIN_FORWARD, WALK_KICK_MIN_SIDE (m), WALK_KICK_TRACE=FILE (then plot it:
# .venv/bin/python3 Tools/plot/plot_walk_kick.py FILE OUT.png)
set -u
source "$(dirname "$0")/kick_sim.sh"
if [ ! -x build/bin/dcm_sim ]; then echo "1..0 # SKIP walk kick: needs build/bin/dcm_sim"; exit 0; fi
echo "1..2"
kick_sim_run "${ROBOT_ID:-9295}" "$KICK_LOGS/main_walk_kick.log" \
  timeout 900 ./run_repl Tests/motion/walk_kick_scenario.lua "${1:-forward=-0.04,-0.02,0,0.035,0.07/-0.03,0.03;side=-0.03,0.03/0}" \
  "${2:-left,right}" "${3:-0.12}"
