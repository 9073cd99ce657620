#!/usr/bin/env bash
# Scenario (make test): the rules of a game in the simulator with a test GameController
# (Tests/game/setplay_play.lua): the other team's free kick (the robot keeps the rules' distance
# from the ball and does not touch it, also after their execute; plays on afterwards), the other
# team's kick-off (stays outside the centre circle for the wait, then plays), the chest button
# (reported; the packets decide), alive return packets.
#   Tests/game/setplay_test.sh        env: ROBOT_ID (uses ROBOT_ID+75), logs in build/test-logs/game/
set -u
cd "$(dirname "$0")/../.."
source Run/env.sh
LOGDIR="$HRP_ROOT/build/test-logs/game"
mkdir -p "$LOGDIR"
ID=$(( ${ROBOT_ID:-9200} + 75 ))
PORT=$((40000 + ID % 20000))   # this run's GameController ports (ids differ per run: no collision)
if [ ! -x build/bin/dcm_sim ]; then echo "1..1"; echo "ok 1 # SKIP needs build/bin/dcm_sim"; exit 0; fi
export ROBOT_ID=$ID HRP_GC_PORT=$PORT HRP_GC_RETURN_PORT=$((PORT + 1)) HRP_TEAM_PORT=$((30000 + ID % 20000))
./run_main --sim --quiet --dcm-arg --lockstep >"$LOGDIR/setplay_main.log" 2>&1 &
MAIN=$!
trap 'kill -TERM $MAIN 2>/dev/null; wait $MAIN 2>/dev/null; Run/shm --robot $ID remove >/dev/null 2>&1' EXIT
for _ in $(seq 1 300); do
  tick=$(Run/shm --robot "$ID" dump sync tick 2>/dev/null | awk '{print $NF}')
  [ -n "$tick" ] && [ "$tick" != 0 ] && break
  sleep 0.1
done
timeout 600 ./run_repl Tests/game/setplay_play.lua "$PORT" "$((PORT + 1))" >"$LOGDIR/setplay_play.log" 2>&1
mapfile -t checks < <(grep '^check ' "$LOGDIR/setplay_play.log")
echo "1..7"
n=0
for c in "${checks[@]}"; do
  n=$((n + 1))
  set -- $c
  if [ "$3" = ok ]; then echo "ok $n - $2: ${c#check $2 ok }"; else echo "not ok $n - $2: ${c#check $2 FAIL }"; fi
done
for i in $(seq $((n + 1)) 7); do echo "not ok $i - missing check (see $LOGDIR/setplay_play.log)"; done
tail -3 "$LOGDIR/setplay_play.log" | sed 's/^/# /'
