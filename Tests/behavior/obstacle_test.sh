#!/usr/bin/env bash
# Scenario (make test): a robot walks to the ball with another robot standing in between, in one
# simulated world (lockstep): it sees the robot (Player/Vision/robots.lua), keeps it as an obstacle
# (the world block) and steps around it (BodyFSM/nav.lua avoid), reaching the ball without touching
# it (Tests/behavior/obstacle_walk.lua).
#   Tests/behavior/obstacle_test.sh     env: ROBOT_ID (uses ROBOT_ID+90, +91), logs in build/test-logs/behavior/
set -u
cd "$(dirname "$0")/../.." || exit 1
source Tests/game/lib.sh
LOGDIR="$HRP_ROOT/build/test-logs/behavior"
mkdir -p "$LOGDIR"
ID=$(( ${ROBOT_ID:-9200} + 90 ))
if [ ! -x build/bin/dcm_sim ]; then echo "1..1"; echo "ok 1 # SKIP needs build/bin/dcm_sim"; exit 0; fi
ROBOT_ID=$ID ./run_dcm --lockstep --robots 2 --seed 5 --quiet >"$LOGDIR/obstacle_dcm.log" 2>&1 &
DCM=$!
MAIN=
cleanup() {
  [ -n "$MAIN" ] && kill -TERM "$MAIN" 2>/dev/null
  sleep 1; kill -TERM "$DCM" 2>/dev/null; wait "$DCM" 2>/dev/null
  Tools/shm/shm --robot "$ID" remove >/dev/null 2>&1; Tools/shm/shm --robot $((ID + 1)) remove >/dev/null 2>&1
}
trap cleanup EXIT
wait_for_clock "$ID"
ROBOT_ID=$ID HRP_SITE="${HRP_SITE:-$HRP_ROOT/Config/site}" HRP_GC_PORT=$((40000 + ID % 20000)) HRP_TEAM_PORT=$((30000 + ID % 20000)) ./run_main --quiet \
  >"$LOGDIR/obstacle_main.log" 2>&1 &
MAIN=$!
ROBOT_ID=$ID timeout 300 ./run_repl Tests/behavior/obstacle_walk.lua >"$LOGDIR/obstacle_walk.log" 2>&1
report_checks "$LOGDIR/obstacle_walk.log" 3
