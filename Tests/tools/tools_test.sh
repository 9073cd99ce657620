#!/usr/bin/env bash
# Scenario (make test): every developer tool in Tools/ runs from where it lives, each on its smallest
# case: a one-item sweep, a tuner started with no generation, a short trace and its plot, a benchmark
# of a second or two, a 1v1 match of 2 s halves, a plot of a tiny trace written here. Each passes when
# it exits 0 and leaves its output (the files it writes, the line it prints). The figures are not
# judged: the tools' own tests and the benchmarks do that. TAP; outputs in build/tmp/tools_test/.
# Not run: Tools/tune/standup_tune.py beyond its usage (it rewrites a body's keyframe files).
set -u
cd "$(dirname "$0")/../.." || exit 1
source Run/env.sh
OUT="$HRP_ROOT/build/tmp/tools_test"
rm -rf "$OUT"; mkdir -p "$OUT"
# robot ids ROBOT_ID+200 and up (run_all.sh gives each test ROBOT_ID..ROBOT_ID+260; the score runs
# below reach +290, short of the next run's ids)
B=$(( ${ROBOT_ID:-9400} + 200 ))
if [ ! -x build/bin/dcm_sim ]; then echo "1..0 # SKIP tools: needs build/bin/dcm_sim (make)"; exit 0; fi

k=0; failed=0
# check NAME CMD...: runs CMD (output in OUT/NAME.log). ok when it exits 0, every file of EXPECT
# (space separated) exists and is not empty, and GREP (an extended regex), if given, matches a line.
check() {
  local name=$1; shift
  local log="$OUT/${name//[^A-Za-z0-9_.-]/_}.log" t0=$SECONDS why="" rc f
  "$@" >"$log" 2>&1
  rc=$?
  [ "$rc" -eq 0 ] || why="exit status $rc"
  for f in ${EXPECT:-}; do [ -s "$f" ] || why="${why:+$why; }no $f"; done
  if [ -n "${GREP:-}" ] && ! grep -Eq "$GREP" "$log"; then why="${why:+$why; }no line matching '$GREP'"; fi
  k=$((k + 1))
  if [ -z "$why" ]; then
    echo "ok $k - $name ($((SECONDS - t0)) s)"
  else
    failed=$((failed + 1))
    echo "not ok $k - $name: $why (log $log)"
    tail -n 8 "$log" | sed 's/^/#   /'
  fi
}

# ---- Tools/shm, Tools/urdf, Tools/deps, Tools/lut
GREP="robot $B: no blocks" check "shm: list a robot's blocks" Tools/shm/shm --robot "$B" list
EXPECT="$OUT/waistbot.urdf" check "urdf: gen_urdf.py writes the waistbot's URDF" \
  python3 Tools/urdf/gen_urdf.py waistbot Config/robots/waistbot/waistbot_reference.txt --out "$OUT/waistbot.urdf"
GREP='all Python packages present' check "deps: install_deps.sh finds everything installed" Tools/deps/install_deps.sh
EXPECT="$OUT/colors.lut" check "lut: lut_tool builds a table from the colour boxes" \
  build/bin/lut_tool colors -o "$OUT/colors.lut"

# ---- Tools/tune and the plots of their traces (the sim in lockstep, the motion process alone)
EXPECT="$OUT/walk.csv $OUT/walk.png" check "tune: walk_trace.lua (the walk generator alone) and plot_walk.py" \
  bash -c "luajit Tools/tune/walk_trace.lua '$OUT/walk.csv' 0.1 0 0 2 &&
           python3 Tools/plot/plot_walk.py '$OUT/walk.csv' '$OUT/walk.png'"
EXPECT="$OUT/kick_left.csv $OUT/kick_left.png" \
  check "tune: kick_trace.sh, one kick traced (kick_measure.lua) and plotted (plot_kick.py)" \
  env ROBOT_ID=$B Tools/tune/kick_trace.sh left 0.1 "$OUT"
GREP='^sweep n=1 ' check "tune: kick_sweep.sh over one ball placement" \
  env ROBOT_ID=$((B + 1)) Tools/tune/kick_sweep.sh left 0.1 0
check "tune: kick_tune.sh starts (no generation)" \
  env ROBOT_ID=$((B + 2)) Tools/tune/kick_tune.sh 0 1 "$OUT/kick_best.lua"
check "tune: walk_kick_tune.sh starts (no iteration)" \
  env ROBOT_ID=$((B + 3)) Tools/tune/walk_kick_tune.sh forward 0 2 "$OUT/walk_kick.lua"
EXPECT="$OUT/turn.csv $OUT/turn.png" check "tune: turn_trace.sh, 2 s traced and plotted (plot_turn.py)" \
  env ROBOT_ID=$((B + 4)) Tools/tune/turn_trace.sh 2.0 2 "$OUT"
EXPECT="$OUT/push.csv $OUT/push.png $OUT/push_feet.png" \
  check "tune: push_trace.sh, one push traced and plotted (plot_push.py, plot_push_feet.py)" \
  env ROBOT_ID=$((B + 5)) Tools/tune/push_trace.sh 20 0 1.0 "$OUT"
GREP='^pushsweep config side ' check "tune: push_sweep.sh, one moment and one force" \
  env ROBOT_ID=$((B + 6)) Tools/tune/push_sweep.sh side 1 10
GREP='^front [0-9]+/1 back [0-9]+/1' check "tune: standup_stats.sh, one trial a side" \
  env ROBOT_ID=$((B + 7)) N=1 WS=2.0 Tools/tune/standup_stats.sh
mkdir -p "$OUT/world"
EXPECT="$OUT/world/record_1.txt" check "tune: behavior_record.lua records a 10 s scoring run" \
  env ROBOT_ID=$((B + 8)) SCORE_BEHAVIOR=Tools/tune/behavior_record.lua WORLD_RECORD_DIR="$OUT/world" SCORE_LIMIT=10 \
  SCORE_NEED=0 SKIP_KILL=1 SCORE_LOGDIR="$OUT/score_record" bash Tests/scenarios/score_test.sh 1
GREP='steps= *[0-9]+ bad=' check "tune: replay_world.lua replays the world model over it" \
  luajit Tools/tune/replay_world.lua "$OUT/world/record_1.txt"
GREP='standup_tune.py NAME' check "tune: standup_tune.py prints its usage" \
  bash -c "python3 Tools/tune/standup_tune.py 2>&1; [ \$? -ne 0 ]"
GREP='toed' check "tune: hip_yaw_clearance.py" python3 Tools/tune/hip_yaw_clearance.py

# ---- Tools/plot on small traces written here in the formats of their sources
python3 - "$OUT" <<'EOF'
import math, os, sys
out = sys.argv[1]
os.makedirs(out + '/score', exist_ok=True)
os.makedirs(out + '/capture', exist_ok=True)
# Tests/scenarios/score_one.lua's trace: t x y yaw bx by fallen px py pyaw wbx wby ball_age body motion
# confidence head, then cmd_vx cmd_vy cmd_va walk_vx walk_vy walk_va
with open(out + '/score/trace_1.txt', 'w') as f:
    for i in range(60):
        t = 0.1 * i
        body = 'search' if i < 20 else 'approach'
        f.write('%.2f %.3f 0.1 0.0 1.0 0.2 0 %.3f 0.1 0.0 1.0 0.2 0.1 %s walk 0.8 track 0.1 0 0 0.1 0 0\n'
                % (t, -1 + 0.02 * i, -1 + 0.02 * i, body))
with open(out + '/score/run_1.log', 'w') as f:
    f.write('result seed=1 goal=1 time=5.9 own=0\n')
# Tools/match/referee.lua's trace with a "# robots N" header: t state bx by, per robot x y yaw fallen
# role, then per robot px py pyaw ball_x ball_y ball_age body_state
with open(out + '/match_trace.txt', 'w') as f:
    f.write('# robots 2\n')
    for i in range(100):
        t = 0.1 * i
        truth = '%.2f 0.0 0 1 %.2f 0.5 3.14 0 2' % (-1 + 0.01 * i, 1 - 0.01 * i)
        view = '-1 0 0 0 0 0.1 1 1 0.5 3.14 0 0 0.1 1'
        f.write('%.1f 3 %.2f 0.0 %s %s\n' % (t, 0.01 * i, truth, view))
# Tests/motion/terrain_scenario.lua's TERRAIN_TRACE
cols = 't x odo_x lx rx com_x pitch imu_pitch gyro_y cp_ex z lz_force rz_force'.split()
with open(out + '/terrain.csv', 'w') as f:
    f.write(','.join(cols) + '\n')
    for i in range(50):
        t = 0.02 * i
        f.write(','.join('%.4f' % v for v in (t, 0.1 * t, 0.1 * t, 0.1 * t, 0.1 * t, 0.1 * t, 0.01, 0.01,
                                               0.1 * math.sin(t), 0.0, 0.0, 20.0, 20.0)) + '\n')
# Tests/motion/walk_kick_scenario.lua's WALK_KICK_TRACE: case t toe_x toe_y toe_z ball_x ball_y ball_z
# torso_x torso_y
with open(out + '/walk_kick.txt', 'w') as f:
    for i in range(30):
        t = 0.02 * i
        f.write('1 %.2f %.3f 0.05 0.02 %.3f 0.05 0.07 %.3f 0.0\n' % (t, 0.01 * i, 0.2 + 0.02 * i, 0.01 * i))
# score_test.sh's CAPTURE_LOGS: t ex ey walking state
with open(out + '/capture/capture_1.txt', 'w') as f:
    for i in range(200):
        f.write('%.3f %.4f %.4f 1 3\n' % (0.008 * i, 0.01 * math.sin(i / 9.0), 0.01 * math.cos(i / 7.0)))
EOF
EXPECT="$OUT/score/trace_1.png" check "plot: plot_paths.py" python3 Tools/plot/plot_paths.py "$OUT/score/trace_1.txt"
GREP='approach' check "plot: trace_stats.py" python3 Tools/plot/trace_stats.py "$OUT/score"
EXPECT="$OUT/match_trace.png" check "plot: plot_match.py" python3 Tools/plot/plot_match.py "$OUT/match_trace.txt"
EXPECT="$OUT/terrain.png" check "plot: plot_terrain.py" \
  python3 Tools/plot/plot_terrain.py "$OUT/terrain.csv" "$OUT/terrain.png"
EXPECT="$OUT/walk_kick.png" check "plot: plot_walk_kick.py" \
  python3 Tools/plot/plot_walk_kick.py "$OUT/walk_kick.txt" "$OUT/walk_kick.png"
EXPECT="$OUT/capture.png" GREP='^play: 200 walking ticks' \
  check "plot: capture_stats.py (play and push_trace.sh's push)" \
  python3 Tools/plot/capture_stats.py "$OUT/capture.png" "$OUT/capture" "$OUT/push.csv"

# ---- Tools/match: a 1v1 match of two 2 s halves (READY 1 s) and the league's table of its log
GREP='^result: team 1 [0-9]+ : [0-9]+ team 2' \
  check "match: match.sh, 1v1, refereed (referee.lua, rules.lua, tally.lua)" \
  env ROBOT_ID=$((B + 10 - 270)) HRP_MATCH_TRACE="$OUT/match_real.txt" Tools/match/match.sh 1 2 1 1
EXPECT="$OUT/match_real.png" check "match: plot_match.py on the match's trace" \
  python3 Tools/plot/plot_match.py "$OUT/match_real.txt"
GREP='matches' check "match: league.py tabulates a referee log" \
  bash -c "python3 Tools/match/league.py --tabulate build/match/$((B + 10))/referee.log"

# ---- Tools/ball_train: one chunk of 10 frames, the classifier trained on its samples
EXPECT="$OUT/ball.mlp" check "ball_train: train.sh on one small chunk" \
  env FRAMES=10 CHUNKS=1 OTHERS=1 Tools/ball_train/train.sh "$OUT/ball.mlp"

# ---- Tools/bench: the runner and each benchmark on its shortest run
GREP='^== kin_leg_ik' check "bench: run_all.sh runs a chosen benchmark (BENCH=kin_leg_ik)" \
  env ROBOT_ID_BENCH=$((B + 20)) BENCH='^kin_leg_ik$' Tools/bench/run_all.sh
GREP='p99' check "bench: shm_latency.lua" env ROBOT_ID=$((B + 28)) luajit Tools/bench/shm_latency.lua 1000
GREP='us' check "bench: motion_tick.lua" luajit Tools/bench/motion_tick.lua 1000
GREP='fps|frames' check "bench: vision_lua.lua" luajit Tools/bench/vision_lua.lua 0.2
GREP='ms|us' check "bench: img_bench (Tools/bench/img_bench.cpp)" build/bin/img_bench 0.2
GREP='fps|frames' check "bench: vision_detect.sh" Tools/bench/vision_detect.sh 0.2
check "bench: dxl_wire.sh" env ROBOT_ID=$((B + 21)) Tools/bench/dxl_wire.sh 1
check "bench: hubo_bus.sh" env ROBOT_ID=$((B + 22)) Tools/bench/hubo_bus.sh 1
check "bench: sim_lockstep.sh" env ROBOT_ID=$((B + 23)) bash Tools/bench/sim_lockstep.sh 2
check "bench: camera_realism.sh" env ROBOT_ID=$((B + 24)) bash Tools/bench/camera_realism.sh 2
check "bench: recorder.sh" env ROBOT_ID=$((B + 25)) Tools/bench/recorder.sh 3
GREP='tick' check "bench: walk_sim.sh tick (one body, one engine)" \
  env ROBOT_ID=$((B + 26)) ROBOTS=op3 ENGINES=analytic Tools/bench/walk_sim.sh tick
check "bench: walk_eye.sh, 2 s of one seed" env ROBOT_ID=$((B + 27 - 450)) Tools/bench/walk_eye.sh 2 1
GREP='^# seed 1' check "bench: score_given_pose.sh, one seed of 5 s" \
  env ROBOT_ID=$((B + 30)) SCORE_LIMIT=5 SCORE_NEED=0 Tools/bench/score_given_pose.sh 1
GREP='^# seed 1' check "bench: white_score.sh (site_white), one seed of 5 s" \
  env ROBOT_ID=$((B + 40 - 400)) SCORE_LIMIT=5 SCORE_NEED=0 Tools/bench/white_score.sh 1
GREP='^ok .*dxl_emulator --sim-id serves' check "bench: dxl_sim_walk.sh, 2 s through the emulated bus" \
  env ROBOT_ID=$((B + 60)) HIL_SECONDS=2 bash Tools/bench/dxl_sim_walk.sh
GREP='falls: [0-9]+ of 1' check "bench: catch_falls.sh, one run" \
  env ROBOT_ID=$((B + 50 - 97)) CATCH_RUNS=1 Tools/bench/catch_falls.sh

echo "1..$k"
[ "$failed" -eq 0 ]
