#!/usr/bin/env bash
# Benchmark: the walk in the simulator (lockstep), a table per body and walk engine, figures only
# (never fails on them):
#  - top forward, sideways and turning speeds sustained for 30 s without a fall (measured from the
#    sim's truth; commands stepped up from 0.8x the body's configured limit until a fall; the limits
#    are raised by half for the search)
#  - the largest sideways and forward pushes (N x 0.1 s) survived while walking: as configured (gyro
#    feedback and step adjustment, Player/Motion/step_adjust.lua), without the step adjustment, and
#    without either
#  - the motion tick's compute time (median, p99) in LuaJIT, robot-free
# The engine is chosen through a site overlay (walk.lua: engine = ...) beside the venue's own files.
# usage: [ROBOTS="op3 darwin hubo2plus"] [ENGINES="analytic preview"] [WALK_SIM_PARAMS="key=v;..."] \
#          [SIM_SEED=N] Tools/bench/walk_sim.sh [speed|push|pushside|tick]...
# (WALK_SIM_PARAMS: walk parameters set first in every run, e.g. to measure a change against the config;
# SIM_SEED: the sim's seed, default 1; pushside: only the side push as configured)
set -u
cd "$(dirname "$0")/../.."
source Run/env.sh
BASE_ID=${ROBOT_ID:-8300}
WHAT=("$@")
[ ${#WHAT[@]} -eq 0 ] && WHAT=(speed push tick)
LOG="$HRP_ROOT/build/test-logs/bench"
mkdir -p "$LOG"
n=0
# run LABEL WALK_PARAMS SCENARIO ARGS...: one scenario in its own sim; prints its figure lines
run() {
  local label=$1 params=$2; shift 2
  n=$((n + 1))
  local id=$((BASE_ID + n))
  Tools/shm/shm --robot "$id" remove >/dev/null 2>&1   # stale segments of an earlier run
  ROBOT_ID=$id ./run_main --sim --quiet --no-restart --dcm-arg --lockstep-wait --dcm-arg 2 \
    --dcm-arg --seed --dcm-arg "${SIM_SEED:-1}" --dcm-arg --no-camera motion >"$LOG/main_$label.log" 2>&1 &
  local pid=$!
  for _ in $(seq 200); do grep -q 'motion started' "$LOG/main_$label.log" 2>/dev/null && break; sleep 0.1; done
  ROBOT_ID=$id WALK_PARAMS="${WALK_SIM_PARAMS:+$WALK_SIM_PARAMS;}$params" timeout 1800 ./run_repl Tests/motion/sim_scenarios.lua "$@" \
    >"$LOG/$label.log" 2>&1
  kill -TERM "$pid" 2>/dev/null; wait "$pid" 2>/dev/null
  Tools/shm/shm --robot "$id" remove >/dev/null 2>&1
  grep -E '^(speed|pushmax) ' "$LOG/$label.log" | tail -1
}
# the body's limits, raised for the search, and the commands to try (from its walk config)
limits() {
  luajit -e "
    local p = require('Config').load('walk')
    local function r(v) return string.format('%.3g', v) end
    local function seq(top) local s = {} for k = 8, 14 do s[#s + 1] = r(top * k / 10) end return table.concat(s, ' ') end
    print(string.format('velLimitX=%s,%s;velLimitY=%s,%s;velLimitA=%s,%s;stepLimitX=%s,%s;stepLimitY=%s,%s;stepLimitA=%s,%s',
      r(p.velLimitX[1] * 1.5), r(p.velLimitX[2] * 1.5), r(p.velLimitY[1] * 1.5), r(p.velLimitY[2] * 1.5),
      r(p.velLimitA[1] * 1.5), r(p.velLimitA[2] * 1.5), r(p.stepLimitX[1] * 1.5), r(p.stepLimitX[2] * 1.5),
      r(p.stepLimitY[1]), r(p.stepLimitY[2] * 1.5), r(p.stepLimitA[1]), r(p.stepLimitA[2] * 1.5)))
    print(seq(p.velLimitX[2])) print(seq(p.velLimitY[2])) print(seq(p.velLimitA[2]))"
}
NOSTEP='stepAdjust.gain=0'
NOFB="feedback.ankle=0,0;feedback.knee=0;feedback.hip=0,0;feedback.arm=0,0;feedback.tilt=0,0;$NOSTEP"
declare -A FIG
ROBOT_LIST=(${ROBOTS:-op3})
ENGINE_LIST=(${ENGINES:-analytic preview})
for robot in "${ROBOT_LIST[@]}"; do
  for engine in "${ENGINE_LIST[@]}"; do
    site="$HRP_ROOT/build/bench-site-$engine"
    rm -rf "$site"; mkdir -p "$site"
    cp Config/site/*.lua "$site/"
    echo "return { engine = '$engine' }  -- Tools/bench/walk_sim.sh" >"$site/walk.lua"
    export ROBOT=$robot HRP_SITE=$site
    mapfile -t L < <(limits)
    k="$robot $engine"
    echo "# $k"
    for w in "${WHAT[@]}"; do
      case $w in
        speed)
          FIG[$k x]=$(run "${robot}_${engine}_speed_x" "${L[0]}" speed x ${L[1]} | awk '{print $3}')
          FIG[$k y]=$(run "${robot}_${engine}_speed_y" "${L[0]}" speed y ${L[2]} | awk '{print $3}')
          FIG[$k a]=$(run "${robot}_${engine}_speed_a" "${L[0]}" speed a ${L[3]} | awk '{print $3}') ;;
        pushside)
          FIG[$k ps]=$(run "${robot}_${engine}_push_side" "" pushmax gyro side | awk '{print $4}') ;;
        push)
          FIG[$k ps]=$(run "${robot}_${engine}_push_side" "" pushmax gyro side | awk '{print $4}')
          FIG[$k psn]=$(run "${robot}_${engine}_push_side_nostep" "$NOSTEP" pushmax nostep side | awk '{print $4}')
          FIG[$k pf]=$(run "${robot}_${engine}_push_fwd" "" pushmax gyro forward | awk '{print $4}')
          FIG[$k pfn]=$(run "${robot}_${engine}_push_fwd_nostep" "$NOSTEP" pushmax nostep forward | awk '{print $4}')
          # the capture point's feedback (Player/Motion/capture.lua) off too, where the body has it
          nofb=$NOFB
          luajit -e "os.exit(rawget(require('Config').load('walk').feedback, 'capture') and 0 or 1)" &&
            nofb="$nofb;feedback.capture=0,0;feedback.captureHip=0,0"
          FIG[$k ps0]=$(run "${robot}_${engine}_push_side_nofb" "$nofb" pushmax nofb side | awk '{print $4}')
          FIG[$k pf0]=$(run "${robot}_${engine}_push_fwd_nofb" "$nofb" pushmax nofb forward | awk '{print $4}') ;;
        tick)
          read -r med p99 < <(luajit Tools/bench/motion_tick.lua 20000 | sed -nE 's/.*median ([0-9.]+) us, p99 ([0-9.]+) us.*/\1 \2/p')
          FIG[$k tick]="$med / $p99" ;;
      esac
    done
  done
done
unset HRP_SITE
echo
echo "| body | engine | forward m/s | sideways m/s | turning rad/s | side push N s (fb+step / fb / none) | forward push N s (fb+step / fb / none) | motion tick us (median / p99) |"
echo "|---|---|---|---|---|---|---|---|"
for robot in "${ROBOT_LIST[@]}"; do
  for engine in "${ENGINE_LIST[@]}"; do
    k="$robot $engine"
    echo "| $robot | $engine | ${FIG[$k x]:--} | ${FIG[$k y]:--} | ${FIG[$k a]:--} | ${FIG[$k ps]:--} / ${FIG[$k psn]:--} / ${FIG[$k ps0]:--} | ${FIG[$k pf]:--} / ${FIG[$k pfn]:--} / ${FIG[$k pf0]:--} | ${FIG[$k tick]:--} |"
  done
done
