#!/usr/bin/env bash
# tier: test (a few seconds: the motion process alone in lockstep, no camera)
# A straight walk ramping its speed does not turn on its support foot nor fall (issue: the OP3 turned about
# 1 rad ramping 0.1 -> 0.4 m/s): per sim seed, 3 s at 0.1 m/s, then 0.1 m/s more per s up to 0.4 m/s, held 5 s
# (Tests/motion/sim_scenarios.lua ramp): the truth's heading stays within 0.25 rad of the ramp's start, no fall,
# and the robot walks on at 0.32 m/s or more along its heading. Prints each seed's figures.
#   Tests/motion/walk_ramp_test.sh [SEEDS...]   (default 1 2 3; ROBOT, ROBOT_ID as sim_walk_test.sh)
set -u
cd "$(dirname "$0")/../.."
SEEDS=("$@")
[ ${#SEEDS[@]} -eq 0 ] && SEEDS=(1 2 3)
n=0; failed=0
for s in "${SEEDS[@]}"; do
  out=$(SIM_SEED=$s Tests/motion/sim_walk_test.sh ramp)
  rc=$?
  while IFS= read -r line; do
    case "$line" in
      "ok "*) n=$((n + 1)); echo "ok $n - seed $s: ${line#ok * - }" ;;
      "not ok "*) n=$((n + 1)); failed=$((failed + 1)); echo "not ok $n - seed $s: ${line#not ok * - }" ;;
      "#"*) echo "$line" ;;
    esac
  done <<<"$out"
  if [ $rc -ne 0 ] && [ $failed -eq 0 ]; then n=$((n + 1)); failed=1; echo "not ok $n - seed $s: the scenario ended with $rc"; fi
done
echo "1..$n"
[ $failed -eq 0 ]
