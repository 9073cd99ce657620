#!/usr/bin/env bash
# Soak: one robot playing in the sim in lockstep (all processes, camera on) for SECONDS of robot time
# (default 3600), the sim seeded with SOAK_SEED (default 1: its sensor noise and everything drawn from it),
# refereed as in a match (Tools/match/rules.lua: a goal, then READY and the other team's kick-off), a new game
# every SOAK_RESTART s (default 180). Samples each process every
# SOAK_SAMPLE s of robot time (default 30): resident memory, open file descriptors, mapped shm segments
# (Tests/soak/soak_play.lua), and checks: no process died or was restarted, fds and segments did not grow,
# and RSS does not grow on after the warm-up (SOAK_WARMUP s, default the first game restart + 30 s or a
# quarter of the run, whichever is longer; it covers a game restart, falls and the camera's widest blur):
# the growth of RSS's high-water mark without its 2 largest steps (one-time high-water marks: buffers,
# arenas, JIT) per simulated second is at most SOAK_DCM_KB_PER_S (default 0.25) for the DCM and
# SOAK_LUA_KB_PER_S (default 4) for the LuaJIT processes (Tests/soak/rss_check.lua). Each process's series,
# rate and steps are printed. `make soak` (1 hour), `make soak SOAK_SECONDS=600 SEED=3` (10 minutes, seed 3);
# Tools/bench/soak_seeds.sh (make soak-seeds): the 10-minute soak on five seeds and the falls over all.
# HRP_SOAK_LEAK_BYTES_PER_S=N: the DCM leaks N bytes per simulated second (Tests/soak/leak_shim.c, preloaded),
# to show that the check catches a leak. The fall census (Tools/match/census.lua): its table printed, the falls
# in build/test-logs/soak/falls.csv and where they happened in falls.png (Tools/plot/plot_falls.py).
#   Tests/soak/soak.sh [SECONDS]   env: ROBOT_ID (uses ROBOT_ID+90), SOAK_SEED, SOAK_RESTART, SOAK_SAMPLE,
#                                       SOAK_WARMUP,
#                                       SOAK_LOGDIR (default build/test-logs/soak),
#                                       SOAK_DCM_KB_PER_S, SOAK_LUA_KB_PER_S, HRP_SOAK_LEAK_BYTES_PER_S
set -u
cd "$(dirname "$0")/../.."
source Run/env.sh
SECS=${1:-${SOAK_SECONDS:-3600}}
EVERY=${SOAK_RESTART:-180}
SEED=${SOAK_SEED:-1}
case "$SEED" in ''|*[!0-9]*) echo "soak.sh: SOAK_SEED must be a whole number >= 0, got '$SEED'" >&2; exit 2 ;; esac
SAMPLE=${SOAK_SAMPLE:-30}
WARM=${SOAK_WARMUP:-$(( EVERY + 30 > SECS / 4 ? EVERY + 30 : SECS / 4 ))}
DCM_RATE=${SOAK_DCM_KB_PER_S:-0.25}
LUA_RATE=${SOAK_LUA_KB_PER_S:-4}
LOGDIR="${SOAK_LOGDIR:-$HRP_ROOT/build/test-logs/soak}"
mkdir -p "$LOGDIR"
ID=$(( ${ROBOT_ID:-9200} + 90 ))
PORT=$((40000 + ID % 20000))
export ROBOT_ID=$ID HRP_GC_PORT=$PORT HRP_GC_RETURN_PORT=$((PORT + 1)) HRP_TEAM_PORT=$((30000 + ID % 20000))
Tools/shm/shm --robot "$ID" remove >/dev/null 2>&1
if [ -n "${HRP_SOAK_LEAK_BYTES_PER_S:-}" ]; then
  # the deliberate leak: a shim around ODE's step, preloaded into every process (only the DCM steps ODE)
  mkdir -p "$HRP_ROOT/build/soak"
  cc -O2 -Wall -Wextra -Werror -shared -fPIC -o "$HRP_ROOT/build/soak/leak_shim.so" Tests/soak/leak_shim.c -ldl ||
    { echo "not ok 1 - the leak shim builds"; exit 1; }
  export HRP_SOAK_LEAK_BYTES_PER_S LD_PRELOAD="$HRP_ROOT/build/soak/leak_shim.so${LD_PRELOAD:+:$LD_PRELOAD}"
fi
./run_main --sim --quiet --dcm-arg --lockstep --dcm-arg --seed --dcm-arg "$SEED" >"$LOGDIR/main.log" 2>&1 &
MAIN=$!
cleanup() { kill -TERM "$MAIN" 2>/dev/null; wait "$MAIN" 2>/dev/null; Tools/shm/shm --robot "$ID" remove >/dev/null 2>&1; }
trap cleanup EXIT
for _ in $(seq 1 300); do
  tick=$(Tools/shm/shm --robot "$ID" dump sync tick 2>/dev/null | awk '{print $NF}')
  [ -n "$tick" ] && [ "$tick" != 0 ] && break
  sleep 0.1
done
t0=$SECONDS
SOAK_FALLS="$LOGDIR/falls.csv" ./run_repl Tests/soak/soak_play.lua "$SECS" "$EVERY" "$PORT" "$MAIN" "$SAMPLE" >"$LOGDIR/soak.out" 2>&1
unset LD_PRELOAD
echo "# $SECS s of robot time in $((SECONDS - t0)) s wall, seed $SEED${HRP_SOAK_LEAK_BYTES_PER_S:+ (the DCM leaking $HRP_SOAK_LEAK_BYTES_PER_S bytes per simulated s)}"
n=0; fails=0
check() { n=$((n + 1)); if [ "$1" = 0 ]; then echo "ok $n - $2"; else fails=$((fails + 1)); echo "not ok $n - $2"; fi; }
result=$(grep '^result' "$LOGDIR/soak.out")
echo "# $result"
sed -n '/^fall census/,/^result/p' "$LOGDIR/soak.out" | grep -v '^result' | sed 's/^/# /'
[ -s "$LOGDIR/falls.csv" ] && "$HRP_ROOT/.venv/bin/python" Tools/plot/plot_falls.py "$LOGDIR/falls.csv" 2>&1 |
  tail -1 | sed 's/^/# /'
[ -n "$result" ]
check $? "the soak ran to its end (${result:-no result; see $LOGDIR/soak.out})"
grep -q 'ended (' "$LOGDIR/main.log"
[ $? -ne 0 ]
check $? "no process ended or was restarted ($(grep -c 'ended (' "$LOGDIR/main.log") ended)"
# fds and shm segments: the first sample after the warm-up against the last
for name in dcm motion vision behavior; do
  s=$(awk -v w="$WARM" -v n="$name" '$1 == "proc" && $2 == n { t = substr($3, 3) + 0; if (t >= w) { print; exit } }' "$LOGDIR/soak.out")
  e=$(grep "^proc $name " "$LOGDIR/soak.out" | tail -1)
  v() { echo "$1" | sed -nE "s/.* $2=([0-9-]+).*/\1/p"; }
  [ -n "$s" ] && [ -n "$e" ] || { check 1 "$name sampled after the warm-up and at the end"; continue; }
  fs=$(v "$s" fds); fe=$(v "$e" fds); ss=$(v "$s" shm); se=$(v "$e" shm)
  [ "$fe" -le "$fs" ] && [ "$se" -le "$ss" ]
  check $? "$name: fds $fs -> $fe, shm segments $ss -> $se (t=$(v "$s" t) s to $(v "$e" t) s)"
done
# RSS: a leak grows on, a high-water mark does not (Tests/soak/rss_check.lua)
while IFS= read -r line; do
  case "$line" in
    "ok - "*) check 0 "${line#ok - }" ;;
    *) check 1 "${line#not ok - }" ;;
  esac
done < <(luajit Tests/soak/rss_check.lua "$LOGDIR/soak.out" "$WARM" "$DCM_RATE" "$LUA_RATE" 2>&1)
a=$(awk -v w="$WARM" '$1 == "robot" && substr($2, 3) + 0 >= w { print; exit }' "$LOGDIR/soak.out" | sed -nE 's/.* segments=([0-9]+).*/\1/p')
b=$(grep '^robot ' "$LOGDIR/soak.out" | tail -1 | sed -nE 's/.* segments=([0-9]+).*/\1/p')
[ -n "$a" ] && [ "$a" = "$b" ]
check $? "the robot's shm segments in /dev/shm: $a -> $b"
echo "1..$n"
[ $fails -eq 0 ]
