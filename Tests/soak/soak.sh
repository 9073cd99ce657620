#!/usr/bin/env bash
# Soak: one robot playing in the sim in lockstep (all processes, camera on) for SECONDS of robot time
# (default 3600), the game restarted every SOAK_RESTART s (default 180). Prints, per process, resident
# memory, open file descriptors and mapped shm segments after the warm-up, half-way and at the end, and
# checks: no process died or was restarted, fds and segments did not grow, RSS grew by at most
# SOAK_RSS_KB (default 4096 KB) per process and by at most half that in the second half (a leak grows
# on; a warm-up does not). `make soak` (1 hour), `make soak SOAK_SECONDS=600` (10 minutes).
#   Tests/soak/soak.sh [SECONDS]   env: ROBOT_ID (uses ROBOT_ID+90), SOAK_RESTART, SOAK_RSS_KB
set -u
cd "$(dirname "$0")/../.."
source Run/env.sh
SECS=${1:-${SOAK_SECONDS:-3600}}
EVERY=${SOAK_RESTART:-180}
RSS_BOUND=${SOAK_RSS_KB:-4096}
LOGDIR="$HRP_ROOT/build/test-logs/soak"
mkdir -p "$LOGDIR"
ID=$(( ${ROBOT_ID:-9200} + 90 ))
PORT=$((40000 + ID % 20000))
export ROBOT_ID=$ID HRP_GC_PORT=$PORT HRP_GC_RETURN_PORT=$((PORT + 1)) HRP_TEAM_PORT=$((30000 + ID % 20000))
Tools/shm/shm --robot "$ID" remove >/dev/null 2>&1
./run_main --sim --quiet --dcm-arg --lockstep --dcm-arg --seed --dcm-arg 1 >"$LOGDIR/main.log" 2>&1 &
MAIN=$!
cleanup() { kill -TERM "$MAIN" 2>/dev/null; wait "$MAIN" 2>/dev/null; Tools/shm/shm --robot "$ID" remove >/dev/null 2>&1; }
trap cleanup EXIT
for _ in $(seq 1 300); do
  tick=$(Tools/shm/shm --robot "$ID" dump sync tick 2>/dev/null | awk '{print $NF}')
  [ -n "$tick" ] && [ "$tick" != 0 ] && break
  sleep 0.1
done
t0=$SECONDS
./run_repl Tests/soak/soak_play.lua "$SECS" "$EVERY" "$PORT" "$MAIN" >"$LOGDIR/soak.out" 2>&1
echo "# $SECS s of robot time in $((SECONDS - t0)) s wall"
n=0; fails=0
check() { n=$((n + 1)); if [ "$1" = 0 ]; then echo "ok $n - $2"; else fails=$((fails + 1)); echo "not ok $n - $2"; fi; }
result=$(grep '^result' "$LOGDIR/soak.out")
echo "# $result"
[ -n "$result" ]
check $? "the soak ran to its end (${result:-no result; see $LOGDIR/soak.out})"
grep -q 'ended (' "$LOGDIR/main.log"
[ $? -ne 0 ]
check $? "no process ended or was restarted ($(grep -c 'ended (' "$LOGDIR/main.log") ended)"
for name in dcm motion vision behavior; do
  s=$(grep "^proc $name start" "$LOGDIR/soak.out"); e=$(grep "^proc $name end" "$LOGDIR/soak.out")
  m=$(grep "^proc $name mid" "$LOGDIR/soak.out")
  v() { echo "$1" | sed -nE "s/.* $2=([0-9-]+).*/\1/p"; }
  [ -n "$s" ] && [ -n "$e" ] || { check 1 "$name sampled at start and end"; continue; }
  rs=$(v "$s" rss_kb); re=$(v "$e" rss_kb); rm=$(v "$m" rss_kb); rm=${rm:-$rs}; fs=$(v "$s" fds); fe=$(v "$e" fds); ss=$(v "$s" shm); se=$(v "$e" shm)
  [ "$(v "$s" pid)" = "$(v "$e" pid)" ] && [ "$fe" -le "$fs" ] && [ "$se" -le "$ss" ] && [ $((re - rs)) -le "$RSS_BOUND" ] &&
    [ $((re - rm)) -le $((RSS_BOUND / 2)) ]
  check $? "$name: RSS $rs -> $rm -> $re KB ($((re - rs)) KB, bound $RSS_BOUND; second half $((re - rm)) KB, bound $((RSS_BOUND / 2))), fds $fs -> $fe, shm segments $ss -> $se"
done
a=$(sed -nE 's/^segments start ([0-9]+).*/\1/p' "$LOGDIR/soak.out"); b=$(sed -nE 's/^segments end ([0-9]+).*/\1/p' "$LOGDIR/soak.out")
[ -n "$a" ] && [ "$a" = "$b" ]
check $? "the robot's shm segments in /dev/shm: $a -> $b"
echo "1..$n"
[ $fails -eq 0 ]
