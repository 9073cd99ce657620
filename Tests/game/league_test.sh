#!/usr/bin/env bash
# Scenario (make test): the league on Ray (Run/league.py, Ray started on this machine): two tiny
# seeded 2v2 matches (2 x 5 s, READY 3 s) as two Ray tasks at once, one team without team play:
# both finish, the table has a row per match and the totals, and Ray is shut down afterwards
# (none of its processes of this run is left).
#   Tests/game/league_test.sh    env: ROBOT_ID (the matches use ROBOT_ID+280.., +288..), log in build/test-logs/game/
set -u
source "$(dirname "$0")/lib.sh"
if [ ! -x build/bin/dcm_sim ]; then echo "1..1"; echo "ok 1 # SKIP needs build/bin/dcm_sim"; exit 0; fi
if ! .venv/bin/python -c 'import ray' 2>/dev/null; then echo "1..1"; echo "not ok 1 - ray is not installed (make deps)"; exit 1; fi
LOG="$LOGDIR/league.log"
BASE=$(( ${ROBOT_ID:-9200} + 10 ))
timeout 300 .venv/bin/python Run/league.py --matches 2 --half 5 --ready 3 --seed 1 --cpus-per-match 1 \
  --id-base "$BASE" --json "$LOGDIR/league.json" >"$LOG" 2>&1
rc=$?
echo "1..3"
rows=$(grep -cE '^ +[12] +[12] ' "$LOG")
if [ "$rc" -eq 0 ] && [ "$rows" -eq 2 ]; then echo "ok 1 - both matches ran as Ray tasks and finished (2 rows)"
else echo "not ok 1 - league exit $rc, $rows rows (see $LOG)"; fi
if grep -q '^total 2 matches' "$LOG" && grep -q '^time in each role' "$LOG"; then
  echo "ok 2 - $(grep '^total' "$LOG")"
else echo "not ok 2 - no totals (see $LOG)"; fi
sleep 2
left=$(pgrep -f "$HRP_ROOT/build/ray/session" | wc -l)
if [ "$left" -eq 0 ]; then echo "ok 3 - Ray shut down: none of its processes left"
else echo "not ok 3 - $left Ray processes left: $(pgrep -af "$HRP_ROOT/build/ray/session" | cut -c1-80 | head -3)"; fi
tail -4 "$LOG" | sed 's/^/# /'
