#!/usr/bin/env bash
# Benchmark: the walk in the simulator (lockstep), figures only (never fails on them):
#  - top forward, sideways and turning speeds sustained for 30 s without a fall (measured from the
#    sim's truth; commands stepped up until a fall; the limits are raised for the search)
#  - the largest sideways push (N x 0.1 s) survived while walking, with and without gyro feedback
# usage: Tests/bench/walk_sim.sh [speed|push]...
set -u
cd "$(dirname "$0")/../.."
source Run/env.sh
BASE_ID=${ROBOT_ID:-8300}
WHAT=("$@")
[ ${#WHAT[@]} -eq 0 ] && WHAT=(speed push)
LOG="$HRP_ROOT/build/test-logs/bench"
mkdir -p "$LOG"
n=0
# run LABEL WALK_PARAMS SCENARIO ARGS...: one scenario in its own sim; prints its figure lines
run() {
  local label=$1 params=$2; shift 2
  n=$((n + 1))
  local id=$((BASE_ID + n))
  Run/shm --robot "$id" remove >/dev/null 2>&1   # stale segments of an earlier run
  ROBOT_ID=$id ./run_main --sim --quiet --no-restart --dcm-arg --lockstep-wait --dcm-arg 2 --dcm-arg --no-camera motion \
    >"$LOG/main_$label.log" 2>&1 &
  local pid=$!
  for _ in $(seq 200); do grep -q 'motion started' "$LOG/main_$label.log" 2>/dev/null && break; sleep 0.1; done
  ROBOT_ID=$id WALK_PARAMS="$params" timeout 1200 ./run_repl Tests/motion/sim_scenarios.lua "$@" \
    >"$LOG/$label.log" 2>&1
  kill -TERM "$pid" 2>/dev/null; wait "$pid" 2>/dev/null
  Run/shm --robot "$id" remove >/dev/null 2>&1
  grep -E '^(speed|pushmax) |^# (speed|pushmax)' "$LOG/$label.log"
}
RAISE='velLimitX=-0.3,0.6;velLimitY=-0.3,0.3;velLimitA=-2.5,2.5;stepLimitX=-0.1,0.16;stepLimitY=0.08,0.25;stepLimitA=-0.05,1.3'
for w in "${WHAT[@]}"; do
  case $w in
    speed)
      run speed_x "$RAISE" speed x 0.35 0.4 0.45 0.5 0.55
      run speed_y "$RAISE" speed y 0.12 0.15 0.18 0.21 0.24
      run speed_a "$RAISE" speed a 1.7 2.0 2.3 2.5 ;;
    push)
      run push_gyro "" pushmax with-gyro-feedback
      run push_nogyro 'feedback.ankle=0,0;feedback.knee=0;feedback.hip=0,0;feedback.arm=0,0' \
        pushmax without-gyro-feedback ;;
  esac
done
