#!/usr/bin/env bash
# The white ball seen by the OP3 walking in the sim (Tests/vision/walk_eye.lua scores it): dcm_sim
# in lockstep with the realistic camera and the white ball (site folder Tests/scenarios/site_white),
# the motion and vision processes, the scorer as the third participant. TAP.
#   WALK_EYE_SECONDS (default 40) of walking per seed, WALK_EYE_SEEDS (default "1"): each seed a run
#   WALK_EYE_GATE: the goals to fail on (default recall,false,bearing: see the figures printed)
# The long run is Tests/bench/walk_eye.sh (make bench).
set -u
cd "$(dirname "$0")/../.."
source Run/env.sh
[ -x build/bin/dcm_sim ] || { echo "not ok 1 - build/bin/dcm_sim not built"; exit 1; }
export HRP_SITE="$PWD/Tests/scenarios/site_white"
export WALK_EYE_GATE="${WALK_EYE_GATE-recall,false,bearing}"
SECONDS_RUN="${WALK_EYE_SECONDS:-40}"
BASE_ID=${ROBOT_ID:-9270}
LOG="$HRP_ROOT/build/test-logs/walk_eye"
mkdir -p "$LOG"
for seed in ${WALK_EYE_SEEDS:-1}; do
  id=$((BASE_ID + seed % 50))
  Run/shm --robot "$id" remove >/dev/null 2>&1
  ROBOT_ID=$id ./run_main --sim --quiet --no-restart --dcm-arg --lockstep --dcm-arg --lockstep-wait \
    --dcm-arg 3 --dcm-arg --seed --dcm-arg "$seed" motion vision >"$LOG/main_$seed.log" 2>&1 &
  main=$!
  for _ in $(seq 300); do grep -q 'vision started' "$LOG/main_$seed.log" 2>/dev/null && break; sleep 0.1; done
  echo "# seed $seed: $SECONDS_RUN s of walking"
  ROBOT_ID=$id timeout 1800 ./run_repl Tests/vision/walk_eye.lua "$SECONDS_RUN" "$seed" | tee "$LOG/run_$seed.log"
  kill -TERM "$main" 2>/dev/null; wait "$main" 2>/dev/null
  Run/shm --robot "$id" remove >/dev/null 2>&1
done
