#!/usr/bin/env bash
# Scenario (make test): the forward kick out of the walk over the OP3's kick zone (the ball 0.17-0.28 m
# ahead of the torso, 0.03-0.09 m to the side, both feet, 20 kicks, walking at 0.12 m/s, seed 1) sends
# every ball >= 1.5 m (the goal) while the robot walks on, no fall. The bench's
# walk_kick_sweep.sh runs the side kick too (make bench).
cd "$(dirname "$0")/../.." || exit 1
ROBOT_ID=${ROBOT_ID:-9297} SIM_SEED=${SIM_SEED:-1} WALK_KICK_MIN_FORWARD=1.5 \
  exec Tests/motion/walk_kick_sweep.sh 'forward=-0.04,-0.02,0,0.035,0.07/-0.03,0.03' left,right 0.12
