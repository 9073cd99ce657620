#!/usr/bin/env bash
# Scenario (make test): run_main restarted during PLAYING. A test GameController (the REPL script
# Tests/game/restart_play.lua) sends PLAYING; once the robot walks, run_main is killed and started
# again while the sim DCM runs on (lockstep): the robot must walk again within 2 s of robot time
# after its new processes are up, and move.
#   Tests/game/restart_test.sh           env: ROBOT_ID (uses ROBOT_ID+70), logs in build/test-logs/game/
set -u
source "$(dirname "$0")/lib.sh"
ID=$(( ${ROBOT_ID:-9200} + 70 ))
PORT=$((40000 + ID % 20000))   # this run's GameController port (ids differ per run: no collision)
echo "1..1"
if [ ! -x build/bin/dcm_sim ]; then echo "ok 1 # SKIP needs build/bin/dcm_sim"; exit 0; fi
export ROBOT_ID=$ID HRP_GC_PORT=$PORT HRP_GC_RETURN_PORT=$((PORT + 1)) HRP_TEAM_PORT=$((30000 + ID % 20000))
PIDFILE="$LOGDIR/restart_main.pid"
./run_dcm --lockstep >"$LOGDIR/restart_dcm.log" 2>&1 &
DCM=$!
cleanup() {
  [ -f "$PIDFILE" ] && kill -TERM "$(cat "$PIDFILE")" 2>/dev/null
  sleep 1; kill -TERM "$DCM" 2>/dev/null; wait "$DCM" 2>/dev/null
  Tools/shm/shm --robot "$ID" remove >/dev/null 2>&1
}
trap cleanup EXIT
wait_for_clock "$ID"
RESTART_CMD="./run_main --quiet >>'$LOGDIR/restart_main.log' 2>&1 & echo \$! >'$PIDFILE'"
: >"$LOGDIR/restart_main.log"
eval "$RESTART_CMD"
RESTART_CMD="$RESTART_CMD" timeout 600 ./run_repl Tests/game/restart_play.lua "$PORT" "$PIDFILE" \
  >"$LOGDIR/restart_play.log" 2>&1
line=$(grep '^result' "$LOGDIR/restart_play.log" | tail -1)
sed 's/^/# /' "$LOGDIR/restart_play.log" | tail -5
after=$(echo "$line" | sed -nE 's/.*walking_after=([-0-9.]+).*/\1/p')
moved=$(echo "$line" | sed -nE 's/.*moved=([-0-9.]+).*/\1/p')
if [ -n "$after" ] && awk -v a="$after" -v m="$moved" 'BEGIN { exit !(a >= 0 && a <= 2.0 && m > 0.15) }'; then
  echo "ok 1 - after a restart during PLAYING the robot walks again after $after s and moves $moved m"
else
  echo "not ok 1 - after a restart during PLAYING: ${line:-no result} (need walking within 2 s, moved > 0.15 m)"
fi
