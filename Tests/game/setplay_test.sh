#!/usr/bin/env bash
# Scenario (make test): the rules of a game in the simulator with a test GameController
# (Tests/game/setplay_play.lua): the other team's free kick (the robot keeps the rules' distance
# from the ball and does not touch it, also after their execute; plays on afterwards), the other
# team's kick-off (stays outside the centre circle for the wait, then plays), the chest button
# (reported; the packets decide), alive return packets.
#   Tests/game/setplay_test.sh        env: ROBOT_ID (uses ROBOT_ID+75), logs in build/test-logs/game/
set -u
source "$(dirname "$0")/lib.sh"
ID=$(( ${ROBOT_ID:-9200} + 75 ))
PORT=$((40000 + ID % 20000))   # this run's GameController ports (ids differ per run: no collision)
if [ ! -x build/bin/dcm_sim ]; then echo "1..1"; echo "ok 1 # SKIP needs build/bin/dcm_sim"; exit 0; fi
export ROBOT_ID=$ID HRP_GC_PORT=$PORT HRP_GC_RETURN_PORT=$((PORT + 1)) HRP_TEAM_PORT=$((30000 + ID % 20000))
./run_main --sim --quiet --dcm-arg --lockstep >"$LOGDIR/setplay_main.log" 2>&1 &
MAIN=$!
trap 'kill -TERM $MAIN 2>/dev/null; wait $MAIN 2>/dev/null; Tools/shm/shm --robot $ID remove >/dev/null 2>&1' EXIT
wait_for_clock "$ID"
timeout 600 ./run_repl Tests/game/setplay_play.lua "$PORT" "$((PORT + 1))" >"$LOGDIR/setplay_play.log" 2>&1
report_checks "$LOGDIR/setplay_play.log" 7
