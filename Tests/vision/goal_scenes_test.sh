#!/usr/bin/env bash
# Goal-post detection over seeded sim scenes (Tests/vision/sim_scenes_test.sh with the scene script
# goal_scenes.lua): dcm_sim in lockstep renders the head camera's view, the script places the robot,
# points the head at a goal or away and runs the vision pipeline. TAP.
#   SCENES=N (default 90), SEED=N (default 1)
set -u
cd "$(dirname "$0")/../.."
SCENE_SCRIPT=Tests/vision/goal_scenes.lua exec bash Tests/vision/sim_scenes_test.sh
