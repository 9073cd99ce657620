#!/usr/bin/env bash
# The lone robot's falls over the 10-minute soak on five seeds (issue's target: at most 0.1 falls per
# minute): Tests/soak/soak.sh SECONDS once per seed, one after the other (each about a minute or two of wall
# time per 10 minutes of robot time here), then each seed's fall census table and result, and the falls per
# minute over all of them (the census's count: one per lying, Tools/match/census.lua). Long: not in make test.
#   Tools/bench/soak_seeds.sh [SECONDS (600)] [SEEDS ("1 2 3 4 5")]     (make soak-seeds)
# env: ROBOT_ID (as soak.sh), logs in build/test-logs/soak_seeds/seed-N/ (soak.out, falls.csv, falls.png).
# Exits non-zero when a soak fails its own checks (memory, fds, shm, no process ended); the falls are figures.
set -u
cd "$(dirname "$0")/../.."
SECS=${1:-600}
SEEDS=${2:-1 2 3 4 5}
BASE=build/test-logs/soak_seeds
status=0 total_falls=0 total_s=0 lines=()
for seed in $SEEDS; do
  dir="$BASE/seed-$seed"
  mkdir -p "$dir"
  SOAK_SEED=$seed SOAK_LOGDIR="$dir" Tests/soak/soak.sh "$SECS" >"$dir/tap.txt" 2>&1 || status=1
  echo "== seed $seed ($(grep -c '^not ok' "$dir/tap.txt") soak checks failed; $dir/tap.txt)"
  sed -n '/^fall census/,/^result/p' "$dir/soak.out" | grep -v '^result'
  result=$(grep '^result' "$dir/soak.out")
  echo "$result"
  f=$(echo "$result" | sed -nE 's/.* falls=([0-9]+).*/\1/p')
  s=$(echo "$result" | sed -nE 's/^result seconds=([0-9]+).*/\1/p')
  [ -n "$f" ] && [ -n "$s" ] || { echo "seed $seed: no result (see $dir/soak.out)"; status=1; continue; }
  total_falls=$((total_falls + f)) total_s=$((total_s + s))
  lines+=("$(awk -v seed="$seed" -v f="$f" -v s="$s" -v g="$(echo "$result" | grep -oE 'goals=[0-9:]+')" \
    'BEGIN { printf "seed %s: %d falls in %.1f min = %.2f per min; %s", seed, f, s / 60, f * 60 / s, g }')")
done
echo "== all seeds"
printf '%s\n' "${lines[@]}"
if [ "$total_s" -gt 0 ]; then
  awk -v f="$total_falls" -v s="$total_s" 'BEGIN {
    printf "soak seeds: %d falls in %.1f robot-minutes = %.3f falls per minute (target: at most 0.1)\n", f, s / 60,
      f * 60 / s }'
fi
exit $status
