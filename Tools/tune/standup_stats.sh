#!/usr/bin/env bash
# Stand-up figure of the body ROBOT (default op3) in the simulator: clean trials, each in a fresh
# sim (lockstep, the motion process alone; Tools/tune/standup_trial.lua): the robot walks, is
# pushed over forwards (front) or backwards (back) and must be walking again within 20 s. A trial
# the push does not topple carries no information and is replaced by the next push moment. Prints
# one line per trial with -v, then
#   front k/n back k/n  (first attempt)     and     eventually: front k/n back k/n
# k/n (first attempt): up with one stand-up motion per side (a back stand-up rolls onto the front
# and then plays the front one once); eventually: up within 20 s, retries allowed.
#   [ROBOT=name] [ROBOT_ID=N] [N=14] [WS="w1 w2 ..."] Tools/tune/standup_stats.sh [-v]
# WS: the walking times before the push (s), tried in order until N trials fell. Tune a stand-up
# on other moments (e.g. 1.9..2.8 by 0.1) than the default set, so that this figure is held out.
set -u
source "$(dirname "$0")/../../Tests/motion/kick_sim.sh"   # the sim in lockstep, shared with the walk-kick test
LOGDIR=$HRP_ROOT/build/test-logs/standup
mkdir -p "$LOGDIR"
verbose=0; [ "${1:-}" = -v ] && verbose=1
N=${N:-14}
ws=${WS:-}
if [ -z "$ws" ]; then
  for k in $(seq 0 39); do ws="$ws $(awk -v k="$k" 'BEGIN { printf "%.3f", 1.96 + 0.065 * k }')"; done
fi
id=${ROBOT_ID:-9300}
declare -A first ever tried
for side in front back; do
  dir=1; [ $side = back ] && dir=-1
  first[$side]=0; ever[$side]=0; tried[$side]=0
  for w in $ws; do
    [ "${tried[$side]}" -ge "$N" ] && break
    r=$(DIR=$dir W=$w kick_sim_run "$id" "$LOGDIR/main_${side}_$w.log" \
      timeout 120 ./run_repl Tools/tune/standup_trial.lua 2>&1 | grep '^RESULT')
    [ $verbose = 1 ] && echo "$r"
    case "$r" in
      *": nofall"*) continue ;;
      *": up attempts front "[01]" back "[01]" "*) first[$side]=$((first[$side] + 1)); ever[$side]=$((ever[$side] + 1)) ;;
      *": up "*) ever[$side]=$((ever[$side] + 1)) ;;
    esac
    tried[$side]=$((tried[$side] + 1))
  done
done
echo "front ${first[front]}/${tried[front]} back ${first[back]}/${tried[back]}  (first attempt)"
echo "eventually: front ${ever[front]}/${tried[front]} back ${ever[back]}/${tried[back]}"
