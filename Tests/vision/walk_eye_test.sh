#!/usr/bin/env bash
# The white ball seen by the OP3 walking in the sim (Tests/vision/walk_eye.lua scores it): dcm_sim
# in lockstep with the realistic camera and the white ball (site folder Tests/scenarios/site_white),
# the motion and vision processes, the scorer as the third participant; one run per seed, the
# figures of all runs together at the end (walk_merge.lua). TAP.
#   WALK_EYE_SECONDS (default 60) of walking per seed, WALK_EYE_SEEDS (default "1 2")
#   WALK_EYE_GATE: the goals to fail on (default recall,false,range,bearing: all met on these seeds and
#   on the bench's 5, README)
# The long run: Tools/bench/walk_eye.sh (make bench).
set -u
cd "$(dirname "$0")/../.."
source Run/env.sh
[ -x build/bin/dcm_sim ] || { echo "not ok 1 - build/bin/dcm_sim not built"; exit 1; }
# WALK_EYE_BALL=orange: the colour table's orange ball (the config's default) instead of the white one
[ "${WALK_EYE_BALL:-white}" = white ] && export HRP_SITE="$PWD/Tests/scenarios/site_white"
GATE="${WALK_EYE_GATE-recall,false,range,bearing}"
SECONDS_RUN="${WALK_EYE_SECONDS:-60}"
SEEDS=(${WALK_EYE_SEEDS:-1 2})
BASE_ID=${ROBOT_ID:-9270}
LOG="$HRP_ROOT/build/test-logs/walk_eye"
mkdir -p "$LOG"
files=()
for seed in "${SEEDS[@]}"; do
  id=$((BASE_ID + seed % 50))
  Tools/shm/shm --robot "$id" remove >/dev/null 2>&1
  ROBOT_ID=$id ./run_main --sim --quiet --no-restart --dcm-arg --lockstep --dcm-arg --lockstep-wait \
    --dcm-arg 3 --dcm-arg --seed --dcm-arg "$seed" motion vision >"$LOG/main_$seed.log" 2>&1 &
  main=$!
  for _ in $(seq 300); do grep -q 'vision started' "$LOG/main_$seed.log" 2>/dev/null && break; sleep 0.1; done
  echo "# seed $seed: $SECONDS_RUN s of walking (log: $LOG/run_$seed.log)"
  rm -f "$LOG/figures_$seed.lua"
  ROBOT_ID=$id WALK_EYE_SAVE="$LOG/figures_$seed.lua" timeout 1800 ./run_repl Tests/vision/walk_eye.lua \
    "$SECONDS_RUN" "$seed" >"$LOG/run_$seed.log" 2>&1
  grep -v '^t ' "$LOG/run_$seed.log" | sed 's/^/#   /'
  kill -TERM "$main" 2>/dev/null; wait "$main" 2>/dev/null
  Tools/shm/shm --robot "$id" remove >/dev/null 2>&1
  [ -s "$LOG/figures_$seed.lua" ] && files+=("$LOG/figures_$seed.lua")
done
if [ ${#files[@]} -ne ${#SEEDS[@]} ]; then
  echo "not ok 1 - a run gave no figures (see $LOG)"
  exit 1
fi
luajit Tests/vision/walk_merge.lua "$GATE" $((SECONDS_RUN * 3 * ${#SEEDS[@]})) "${files[@]}"
