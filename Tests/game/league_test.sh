#!/usr/bin/env bash
# Scenario (make test): the league on Ray (Tools/match/league.py, Ray started on this machine): two tiny
# seeded 2v2 matches (2 x 5 s, READY 3 s) as two Ray tasks at once, one team without team play:
# both finish, the table has a row per match and the totals, and Ray is shut down afterwards
# (none of its processes of this run is left). Then a league stopped with SIGTERM while its match
# plays: within 20 s none of the match's processes and none of its shared memory blocks is left.
#   Tests/game/league_test.sh    env: ROBOT_ID (the matches use ROBOT_ID+280.., +288..), log in build/test-logs/game/
set -u
source "$(dirname "$0")/lib.sh"
if [ ! -x build/bin/dcm_sim ]; then echo "1..1"; echo "ok 1 # SKIP needs build/bin/dcm_sim"; exit 0; fi
if ! .venv/bin/python -c 'import ray' 2>/dev/null; then echo "1..1"; echo "not ok 1 - ray is not installed (make deps)"; exit 1; fi
LOG="$LOGDIR/league.log"
BASE=$(( ${ROBOT_ID:-9200} + 10 ))
timeout 300 .venv/bin/python Tools/match/league.py --matches 2 --half 5 --ready 3 --seed 1 --cpus-per-match 1 \
  --id-base "$BASE" --json "$LOGDIR/league.json" >"$LOG" 2>&1
rc=$?
echo "1..4"
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

# ---- a league stopped while its match plays
STOP_BASE=$(( BASE + 40 ))
MATCH_ID=$(( STOP_BASE + 270 ))   # match.sh's first robot (its robots: MATCH_ID .. MATCH_ID+3)
# processes whose environment names one of the match's robots
match_procs() {
  for pid in $(pgrep -f 'luajit|dcm_sim|match.sh'); do
    tr '\0' '\n' </proc/"$pid"/environ 2>/dev/null | grep -qxE "ROBOT_ID=($MATCH_ID|$((MATCH_ID + 1))|$((MATCH_ID + 2))|$((MATCH_ID + 3)))" \
      && echo "$pid"
  done
}
match_blocks() { ls /dev/shm 2>/dev/null | grep -cE "^hrp\.($MATCH_ID|$((MATCH_ID + 1))|$((MATCH_ID + 2))|$((MATCH_ID + 3)))\."; }
.venv/bin/python Tools/match/league.py --matches 1 --half 60 --ready 3 --seed 1 --id-base "$STOP_BASE" \
  >"$LOGDIR/league_stop.log" 2>&1 &
league=$!
# until every robot's behavior block exists and the game has run a little
for _ in $(seq 1 240); do
  [ -e "/dev/shm/hrp.$((MATCH_ID + 3)).world" ] && break
  sleep 0.5
done
sleep 5
before=$(match_blocks); nproc=$(match_procs | wc -l)
kill -TERM "$league"
gone=no
for t in $(seq 1 40); do
  sleep 0.5
  if [ "$(match_blocks)" -eq 0 ] && [ -z "$(match_procs)" ] && ! kill -0 "$league" 2>/dev/null; then gone=yes; break; fi
done
if [ "$before" -gt 0 ] && [ "$nproc" -gt 0 ] && [ "$gone" = yes ]; then
  echo "ok 4 - the league stopped with SIGTERM mid-match: its $nproc processes and $before blocks gone after $(echo "$t * 0.5" | bc) s"
else
  echo "not ok 4 - league stopped mid-match ($nproc processes and $before blocks before): left $(match_procs | wc -l) processes, $(match_blocks) blocks (see $LOGDIR/league_stop.log)"
  for pid in $(match_procs); do kill -KILL "$pid" 2>/dev/null; done
  for i in 0 1 2 3; do Tools/shm/shm --robot $((MATCH_ID + i)) remove >/dev/null 2>&1; done
fi
