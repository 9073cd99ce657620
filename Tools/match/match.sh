#!/usr/bin/env bash
# A whole match, unattended: two teams of PER_TEAM robots in one simulated world (lockstep), each
# robot its own ROBOT_ID, run_main and site folder (team and player number), refereed by
# Tools/match/referee.lua (a GameController: packets, return packets, the sim's truth). Prints the events,
# the result (goals, own goals, falls (one per lying, as the fall census counts them), penalties), the
# real-time factor and the CPU per process kind.
#   Tools/match/match.sh [PER_TEAM (2)] [HALF_SECONDS (300)] [SEED (1)] [READY_SECONDS (45)]
# (make match, make match4). The referee's rules are Config/common/game.lua's `referee`; the half and
# READY's length given here reach it through its own site folder (build/match/<id>/site_referee/game.lua).
# env: ROBOT_ID (robots ROBOT_ID+270 ..; UDP ports derived from it), logs in build/match/<first id>/
# (trace.txt: where everyone was every 0.1 s, for Tools/plot/plot_match.py; HRP_MATCH_TRACE= for none;
# falls.csv and falls.png: the fall census's falls and where on the field, Tools/plot/plot_falls.py);
# ALONE="2" (team numbers, space-separated): those teams' robots play without team play (no team
# messages, no roles: each robot alone; game.lua's team.enabled, roles.enabled), for Tools/match/league.py.
# The robots see each other (jerseys in the sim camera, the vision block's robots, the world's obstacles) and walk
# around them on the way to a point (BodyFSM/nav.lua; teammates also from their messages); dribbling turns its
# aim round a robot in the lane ahead of the ball (BodyFSM/dribble.lua).
set -u
cd "$(dirname "$0")/../.." || exit 1
source Run/env.sh
N=${1:-2}
HALF=${2:-300}
SEED=${3:-1}
READY=${4:-}
ID=$(( ${ROBOT_ID:-46000} + 270 ))
R=$((2 * N))
DIR="$HRP_ROOT/build/match/$ID"
mkdir -p "$DIR"
# ports from the id: GameController and its return port, one team-message port per team
GC_PORT=$((50000 + (ID % 5000) * 2))
RET_PORT=$((GC_PORT + 1))
TEAM_PORT=$((20000 + (ID % 5000) * 2))
PIDS=()
cleanup() {
  [ -n "${WATCH:-}" ] && kill "$WATCH" 2>/dev/null
  [ -n "${REF:-}" ] && kill -TERM "$REF" 2>/dev/null
  for p in "${PIDS[@]}"; do kill -TERM "$p" 2>/dev/null; done
  # run_main stops its processes (SIGKILL after 3 s): wait for it, or a process still running could
  # write into a block after it is removed
  for p in "${PIDS[@]}"; do wait "$p" 2>/dev/null; done
  [ -n "${DCM:-}" ] && kill -TERM "$DCM" 2>/dev/null && wait "$DCM" 2>/dev/null
  for i in $(seq 0 $((R - 1))); do Tools/shm/shm --robot $((ID + i)) remove >/dev/null 2>&1; done
}
trap cleanup EXIT
# A parent that dies without a word (Tools/match/league.py's Ray worker, killed when the league is stopped)
# ends the match the same way, so no process or block is left behind
PARENT=$PPID
( while kill -0 "$PARENT" 2>/dev/null; do sleep 1; done; kill -TERM $$ ) &
WATCH=$!
# every robot's three processes and the referee join before the first tick: the same start every run
ROBOT_ID=$ID ./run_dcm --lockstep-wait $((3 * R + 1)) --robots "$R" --seed "$SEED" --quiet \
  >"$DIR/dcm.log" 2>&1 &
DCM=$!
sleep 1
for i in $(seq 0 $((R - 1))); do
  team=$((i < N ? 1 : 2)); player=$((i < N ? i + 1 : i - N + 1))
  site="$DIR/site_${team}_${player}"
  mkdir -p "$site"
  cp Config/site/vision.lua "$site/"
  # the referee places team 1 on the touch line at its right in the first half (y = -W, its own
  # goal at -x), team 2 on its left: the robots know it (the pose filter's side)
  side=$([ "$team" = 1 ] && echo right || echo left)
  printf 'return { team_number = %d, player_number = %d, world = { pose = { placement = "%s" } } }\n' \
    "$team" "$player" "$side" >"$site/behavior.lua"
  rm -f "$site/game.lua"
  for t in ${ALONE:-}; do
    [ "$t" = "$team" ] && printf 'return { team = { enabled = false }, roles = { enabled = false } }\n' >"$site/game.lua"
  done
  ROBOT_ID=$((ID + i)) HRP_SITE="$site" HRP_GC_PORT=$GC_PORT HRP_GC_RETURN_PORT=$RET_PORT \
    HRP_TEAM_PORT=$((TEAM_PORT + team - 1)) ./run_main --quiet >"$DIR/main_${team}_${player}.log" 2>&1 &
  PIDS+=($!)
done
mkdir -p "$DIR/site_referee"
printf 'return { referee = { half_time = %s%s } }\n' "$HALF" "${READY:+, ready_time = $READY}" \
  >"$DIR/site_referee/game.lua"
START=$(date +%s.%N)
# in the background with its pid kept, so that the cleanup can stop it (a signal ends `wait` at once)
HRP_MATCH_FALLS="$DIR/falls.csv" HRP_MATCH_TRACE="${HRP_MATCH_TRACE-$DIR/trace.txt}" ROBOT_ID=$ID HRP_SITE="$DIR/site_referee" ./run_repl Tools/match/referee.lua "$N" "$GC_PORT" "$RET_PORT" \
  > >(tee "$DIR/referee.log") 2>&1 &
REF=$!
wait "$REF"
STATUS=$?
REF=
END=$(date +%s.%N)
# where the time went: CPU seconds of each kind of process (the robots' processes are run_main's children)
kids=$(for p in "${PIDS[@]}"; do pgrep -P "$p"; done | tr '\n' ',')
ps -o times=,args= -p "${kids%,},$DCM" | awk -v wall="$(echo "$END - $START" | bc)" '
  { k = $2; if ($2 ~ /dcm_sim/) k = "dcm_sim (physics, cameras)"; else if ($3 ~ /Motion/) k = "motion"
    else if ($3 ~ /Vision/) k = "vision"; else if ($3 ~ /Behavior/) k = "behavior"
    cpu[k] += $1; all += $1 }
  END { printf "CPU over %.0f s wall (%.0f%% of one core in all):\n", wall, 100 * all / wall
        for (k in cpu) printf "  %-28s %7.1f s  %5.1f%%\n", k, cpu[k], 100 * cpu[k] / all }'
[ -s "$DIR/falls.csv" ] && "$HRP_ROOT/.venv/bin/python" Tools/plot/plot_falls.py "$DIR/falls.csv" 2>&1 | tail -1
exit "$STATUS"
