#!/usr/bin/env bash
# Scenario (make test): a short refereed 2v2 match (Tools/match/match.sh: halves of 15 s, READY 10 s):
# the referee takes the game through both halves to the end and prints the result, every robot
# answers the GameController (return packets), no robot process dies, and no robot's pose belief
# is the mirror of the truth for more than 2 s in all (the side: Player/World/pose_filter.lua).
#   Tests/game/match_test.sh      env: ROBOT_ID (the match uses ROBOT_ID+270 ..), logs in build/match/<id>/
set -u
source "$(dirname "$0")/lib.sh"
if [ ! -x build/bin/dcm_sim ]; then echo "1..1"; echo "ok 1 # SKIP needs build/bin/dcm_sim"; exit 0; fi
ID=$(( ${ROBOT_ID:-9200} + 270 ))
LOG="$LOGDIR/match.log"
ROBOT_ID=${ROBOT_ID:-9200} timeout 600 Tools/match/match.sh 2 15 1 10 >"$LOG" 2>&1
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
  tallies=$(grep '^tally ' "$LOG")
  worst=$(echo "$tallies" | grep -o 'mirrored=[0-9.]*' | cut -d= -f2 | sort -g | tail -1)
  [ "$(echo "$tallies" | wc -l)" = 4 ] && awk -v w="${worst:-99}" 'BEGIN { exit !(w <= 2.0) }'
  check side $? "the longest mirrored belief of a robot ${worst:-?} s ($(echo "$tallies" | grep -o '^tally [0-9/]*.*mirrored=[0-9.]*' | sed 's/striker.*mirrored/mirrored/' | tr '\n' ';'))"
} >"$LOGDIR/match_checks.log"
report_checks "$LOGDIR/match_checks.log" 4
