#!/usr/bin/env bash
# Scenario (make test): a short refereed 2v2 match (Tests/bench/match.sh: halves of 15 s, READY 10 s):
# the referee takes the game through both halves to the end and prints the result, every robot
# answers the GameController (return packets), and no robot process dies.
#   Tests/game/match_test.sh      env: ROBOT_ID (the match uses ROBOT_ID+270 ..), logs in build/match/<id>/
set -u
source "$(dirname "$0")/lib.sh"
if [ ! -x build/bin/dcm_sim ]; then echo "1..1"; echo "ok 1 # SKIP needs build/bin/dcm_sim"; exit 0; fi
ID=$(( ${ROBOT_ID:-9200} + 270 ))
LOG="$LOGDIR/match.log"
ROBOT_ID=${ROBOT_ID:-9200} timeout 600 Tests/bench/match.sh 2 15 1 10 >"$LOG" 2>&1
STATUS=$?
DIR="$HRP_ROOT/build/match/$ID"
check() { if [ "$2" = 0 ]; then echo "check $1 ok $3"; else echo "check $1 FAIL $3"; fi; }
{
  n=$(grep -c ' playing$' "$LOG"); f=$(grep -c ' finished$' "$LOG")
  [ "$n" = 2 ] && [ "$f" = 2 ] && grep -q '^result: ' "$LOG"
  check halves $? "$(grep '^result' "$LOG") (PLAYING entered $n times, FINISHED $f; exit $STATUS)"
  line=$(grep '^return packets' "$LOG")
  counts=$(echo "$line" | grep -o ':[0-9]*' | tr -d ':' | tr '\n' ' ')
  ok=0; k=0
  for c in $counts; do k=$((k + 1)); [ "$c" -gt 0 ] || ok=1; done
  [ "$k" = 4 ] || ok=1
  check return_packets $ok "$line"
  died=$(cat "$DIR"/main_*.log 2>/dev/null | grep -ci 'exited\|error\|restart')
  [ "$died" = 0 ]
  check no_crash $? "$died lines of dying or restarting processes in $DIR/main_*.log"
} >"$LOGDIR/match_checks.log"
report_checks "$LOGDIR/match_checks.log" 3
