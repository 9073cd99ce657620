#!/usr/bin/env bash
# Scenario (make test): two robots of one team in one simulated world (lockstep), players 1 and 2,
# talking over UDP with the league's message (Tests/game/team_play.lua): they hear each other, the
# one nearer the ball strikes and the other defends; when the striker's run_main is stopped the
# defender takes the striker's role over and goes for the ball.
#   Tests/game/team_test.sh        env: ROBOT_ID (uses ROBOT_ID+80, +81), logs in build/test-logs/game/
set -u
source "$(dirname "$0")/lib.sh"
ID=$(( ${ROBOT_ID:-9200} + 80 ))
if [ ! -x build/bin/dcm_sim ]; then echo "1..1"; echo "ok 1 # SKIP needs build/bin/dcm_sim"; exit 0; fi
# player 2's site folder (inside the repository's build/)
SITE2="$HRP_ROOT/build/test-logs/game/site_player2"
mkdir -p "$SITE2"
cp Config/site/vision.lua "$SITE2/"
printf 'return { team_number = 1, player_number = 2 }\n' >"$SITE2/behavior.lua"
# one team port for both, GameController ports of their own (no GameController: the sim's quick start)
export HRP_TEAM_PORT=$((30000 + ID % 20000))
PIDFILE="$LOGDIR/team_main2.pid"
ROBOT_ID=$ID ./run_dcm --lockstep --robots 2 --seed 3 --quiet >"$LOGDIR/team_dcm.log" 2>&1 &
DCM=$!
cleanup() {
  kill -TERM "$MAIN1" "$(cat "$PIDFILE" 2>/dev/null)" 2>/dev/null
  sleep 1; kill -TERM "$DCM" 2>/dev/null; wait "$DCM" 2>/dev/null
  Tools/shm/shm --robot "$ID" remove >/dev/null 2>&1; Tools/shm/shm --robot $((ID + 1)) remove >/dev/null 2>&1
}
MAIN1=
trap cleanup EXIT
wait_for_clock "$ID"
ROBOT_ID=$ID HRP_GC_PORT=$((40000 + ID % 20000)) ./run_main --quiet >"$LOGDIR/team_main1.log" 2>&1 &
MAIN1=$!
ROBOT_ID=$((ID + 1)) HRP_SITE="$SITE2" HRP_GC_PORT=$((40002 + ID % 20000)) ./run_main --quiet \
  >"$LOGDIR/team_main2.log" 2>&1 &
echo $! >"$PIDFILE"
ROBOT_ID=$ID timeout 600 ./run_repl Tests/game/team_play.lua "$PIDFILE" >"$LOGDIR/team_play.log" 2>&1
report_checks "$LOGDIR/team_play.log" 4
