#!/usr/bin/env bash
# Runs every benchmark and prints its figures (never fails on time). `make bench`.
# One benchmark per line below; BENCH=regex runs a subset.
set -u
cd "$(dirname "$0")/../.."
source Run/env.sh
export ROBOT_ID="${ROBOT_ID_BENCH:-$((8000 + $$ % 500))}"
FILTER="${BENCH:-.}"
bench() {
  local name=$1; shift
  echo "$name" | grep -Eq "$FILTER" || return 0
  echo "== $name"
  "$@" || echo "(benchmark $name exited with status $?)"
  echo
}
bench shm_latency luajit Tools/bench/shm_latency.lua 100000
bench kin_leg_ik luajit Tools/bench/kin_leg_ik.lua 100000
bench dynamics build/bin/dyn_bench 20000 hubo2plus
bench wbc build/bin/wbc_bench 5000 hubo2plus
bench vision_pipeline build/bin/img_bench 2
bench motion_tick luajit Tools/bench/motion_tick.lua 50000
bench dxl_wire Tools/bench/dxl_wire.sh 4
bench hubo_bus Tools/bench/hubo_bus.sh 5
bench vision_lua luajit Tools/bench/vision_lua.lua 2
bench vision_detect Tools/bench/vision_detect.sh 2
bench white_score Tools/bench/white_score.sh
bench walk_eye Tools/bench/walk_eye.sh
bench sim_lockstep bash Tools/bench/sim_lockstep.sh 30
bench camera_realism bash Tools/bench/camera_realism.sh 40
bench walk_sim Tools/bench/walk_sim.sh
bench walk_kick Tests/motion/walk_kick_sweep.sh
bench score_given_pose Tools/bench/score_given_pose.sh
bench standup_op3 env ROBOT=op3 Tools/tune/standup_stats.sh
bench standup_darwin env ROBOT=darwin Tools/tune/standup_stats.sh
bench recorder Tools/bench/recorder.sh 20
bench game_replay bash Tests/replay/game_replay_test.sh 120
bench darwin_score env SCORE_NEED=9 bash Tests/scenarios/darwin_score_test.sh
bench hoap3_score bash Tools/bench/hoap3_score.sh
bench hil_walk_op3 bash Tools/bench/dxl_sim_walk.sh
bench hubo_balance_push bash Tests/motion/hubo_balance_test.sh push
