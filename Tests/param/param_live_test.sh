#!/usr/bin/env bash
# tier: check (make check runs it: a few seconds)
# Live parameters (TAP): the sim in lockstep with the motion and vision processes; a REPL script
# (Tests/param/param_live.lua) changes walk.tStep and vision.ball.max_range in the running processes
# and measures their effect, then param.save() writes walk.tStep into the site overlay of this test
# (a copy of Config/site plus a walk.lua that sets tStep): checked here to load with the new value,
# its comment kept and nothing else changed.
set -u
cd "$(dirname "$0")/../.."
source Run/env.sh
LOGDIR="$HRP_ROOT/build/test-logs/param"
mkdir -p "$LOGDIR"
id=$(( ${ROBOT_ID:-9200} + 70 ))
site=$(mktemp -d)
trap 'rm -rf "$site"; Tools/shm/shm --robot "$id" remove >/dev/null 2>&1' EXIT
cp Config/site/*.lua "$site/"
printf -- '-- this venue walks its own way\nreturn {\n  tStep = 0.25, -- s, one step (tuned here)\n}\n' > "$site/walk.lua"
cp "$site/walk.lua" "$site/walk.lua.orig"
export HRP_SITE="$site"
Tools/shm/shm --robot "$id" remove >/dev/null 2>&1
ROBOT_ID=$id ./run_main --sim --quiet --no-restart --dcm-arg --lockstep-wait --dcm-arg 3 motion vision \
  >"$LOGDIR/main.log" 2>&1 &
main_pid=$!
for _ in $(seq 200); do grep -q 'vision started' "$LOGDIR/main.log" 2>/dev/null && break; sleep 0.1; done
ROBOT_ID=$id timeout 600 ./run_repl Tests/param/param_live.lua | tee "$LOGDIR/scenario.log" | grep -v '^1\.\.'
rc=${PIPESTATUS[0]}
kill -TERM "$main_pid" 2>/dev/null
wait "$main_pid" 2>/dev/null
grep '\[param\]' "$LOGDIR/main.log" | sed 's/^/# /'
n=$(grep -c '^\(not \)\?ok ' "$LOGDIR/scenario.log")
fails=0
res() { n=$((n + 1)); if [ "$1" = 0 ]; then echo "ok $n - $2"; else fails=$((fails + 1)); echo "not ok $n - $2"; fi; }
diff "$site/walk.lua.orig" "$site/walk.lua" | sed 's/^/# /'
[ "$(diff "$site/walk.lua.orig" "$site/walk.lua" | grep -c '^[<>]')" = 2 ] &&
  grep -qx '  tStep = 0.32, -- s, one step (tuned here)' "$site/walk.lua"
res $? "the saved site walk.lua differs in the value only (comments kept)"
v=$(luajit -e "package.path='Lib/?.lua;'..package.path; print(require('Config').load('walk').tStep)")
[ "$v" = 0.32 ]
res $? "the saved file loads through Config with walk.tStep = 0.32 (got $v)"
echo "1..$n"
[ "$rc" = 0 ] && [ "$fails" = 0 ]
