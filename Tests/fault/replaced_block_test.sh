#!/usr/bin/env bash
# Scenario (make test, real time): shm blocks replaced while the robot plays (`./run_main --sim`).
#   1. `world` removed (behavior writes it, run_main reads it);
#   2. `vision` recreated with another layout (a field more, by a process with its own schema that
#      then ends), which vision writes and behavior and run_main read.
# Checks: each process holding the block exits naming it (Lib/shm_watch.lua) and run_main restarts
# it; run_main maps the block again; the restarted processes work on the new segment (vision's frames
# and behavior's steps go on, the new `world` is written). Prints the time from the replacement to
# the work going on again (wall s).
#   env: ROBOT_ID (uses ROBOT_ID+95)
set -u
cd "$(dirname "$0")/../.."
source Run/env.sh
ID=$(( ${ROBOT_ID:-9200} + 95 ))
export ROBOT_ID=$ID HRP_GC_PORT=$((40000 + ID % 20000)) HRP_GC_RETURN_PORT=$((40001 + ID % 20000))
export HRP_TEAM_PORT=$((30000 + ID % 20000))
LOGDIR="$HRP_ROOT/build/test-logs/fault"
mkdir -p "$LOGDIR"
LOG=$LOGDIR/replaced_main.log
T=$(mktemp -d)
n=0 fails=0
ok() { n=$((n + 1)); if [ "$1" = 0 ]; then echo "ok $n - $2"; else echo "not ok $n - $2"; fails=$((fails + 1)); fi; }
if [ ! -x build/bin/dcm_sim ]; then echo "1..1"; echo "ok 1 # SKIP needs build/bin/dcm_sim"; exit 0; fi
Tools/shm/shm --robot "$ID" remove >/dev/null 2>&1
./run_main --sim >"$LOG" 2>&1 &
MAIN=$!
cleanup() {
  kill -TERM "$MAIN" 2>/dev/null; wait "$MAIN" 2>/dev/null
  Tools/shm/shm --robot "$ID" remove >/dev/null 2>&1
  rm -rf "$T"
}
trap cleanup EXIT
wait_until() { local end=$((SECONDS + $1)); shift; until "$@" >/dev/null 2>&1; do [ $SECONDS -ge $end ] && return 1; sleep 0.1; done; }
field() { luajit -e "local b = require('shm').open('$1', { attach = true, raw = true }) print(b.$2[0])" 2>/dev/null; }
# moves BLOCK FIELD: the field changes within 2 s (the work goes on)
moves() { local a; a=$(field "$1" "$2"); sleep 2; [ -n "$a" ] && [ "$(field "$1" "$2")" != "$a" ]; }
pid_changed() { [ -n "$(pid_of "$1")" ] && [ "$(pid_of "$1")" != "$2" ]; }
pid_of() { sed -nE "s/.*$1 started \(pid ([0-9]+)\).*/\1/p" "$LOG" | tail -1; }
wall() { date +%s.%N; }
secs() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.1f", b - a }'; }

wait_until 60 moves vision frame && wait_until 30 moves game time
ok $? "the robot plays: vision's frames and behavior's steps go on"

# 1. world removed
b0=$(pid_of behavior)
t0=$(wall)
luajit -e "require('shm').C.shm_block_unlink('world', $ID)"
wait_until 10 grep -q 'behavior: shm block(s) world replaced under this process' "$LOG"
ok $? "behavior exits naming the removed block world"
wait_until 10 grep -q 'shm block world was replaced: mapped again' "$LOG"
ok $? "run_main maps world again"
wait_until 30 pid_changed behavior "$b0"
b1=$(pid_of behavior)
wait_until 30 moves world time; rc=$?
t1=$(wall)
ok $rc "run_main restarts behavior (pid $b0 -> $b1), which writes the new world block ($(secs "$t0" "$t1") s after the removal)"
echo "# figure: replaced:world working_again_s=$(secs "$t0" "$t1")"

# 2. vision recreated with another layout by a process that then ends
v0=$(pid_of vision); b0=$(pid_of behavior)
sed '/^block vision$/a\  f64 extra 1' Config/shm.schema >"$T/schema"
for c in Config/robots/*/shm.consts; do [ -f "$c" ] && cp "$c" "$T/"; done
t0=$(wall)
HRP_SCHEMA=$T/schema luajit -e "local shm = require('shm') shm.C.shm_block_unlink('vision', $ID) assert(shm.open('vision').extra)"
ok $? "vision recreated with a field more (its own schema)"
wait_until 10 grep -q 'vision: shm block(s) vision replaced under this process' "$LOG"
ok $? "vision exits naming the recreated block"
wait_until 10 grep -qE 'behavior: shm block\(s\) (.*, )?vision' "$LOG"
ok $? "behavior, which reads vision, exits naming it"
wait_until 30 pid_changed vision "$v0"
wait_until 60 moves vision frame && wait_until 30 moves game time; rc=$?
t1=$(wall)
ok $rc "vision and behavior restarted (vision $v0 -> $(pid_of vision), behavior $b0 -> $(pid_of behavior)) work on a vision block of the schema's layout ($(secs "$t0" "$t1") s after)"
echo "# figure: replaced:vision working_again_s=$(secs "$t0" "$t1")"
luajit -e "assert(require('shm').open('vision', { attach = true }))" 2>&1 | head -2 | sed 's/^/# /'
grep -E 'replaced|ended|mapped again' "$LOG" | sed 's/^/# main: /'
echo "1..$n"
[ $fails -eq 0 ]
