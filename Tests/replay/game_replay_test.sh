#!/usr/bin/env bash
# A game recorded in the sim and replayed through the unchanged vision and behavior processes (TAP):
#   1. the sim in lockstep plays SECONDS of a game (one robot: motion, vision, behavior; no GameController:
#      the sim's quick start) while hrp_record --lockstep records every tick with lossless camera frames;
#   2. PLATFORM=Replay serves that log in lockstep (dcm.sensor, camera.image, the sim truth and motion's own
#      fields of the motion block) to vision and behavior, recorded again;
#   3. tick by tick, the replayed vision, world, game and team blocks and the behavior's fields of the motion
#      block equal the recorded ones bit for bit (Tests/replay/compare_logs.py);
#   4. a swapped process: the same log replayed through vision with another ball detector setting gives other
#      detections and another world model (the way to test a changed detector on a recorded game).
# The processes under test run with the recording's configuration (PLATFORM=Sim: its quick start); only the DCM
# is the Replay platform's.
#   Tests/replay/game_replay_test.sh [SECONDS]      default 25; the 2-minute game: make bench (game_replay)
set -u
cd "$(dirname "$0")/../.."
source Run/env.sh
SECONDS_SIM=${1:-25}
REC_ID=$(( ${ROBOT_ID:-9200} + 100 ))
REP_ID=$(( ${ROBOT_ID:-9200} + 101 ))
dir=$(mktemp -d)
pids=()
cleanup() {
  for p in "${pids[@]}"; do kill -TERM "$p" 2>/dev/null; done
  sleep 0.3
  for p in "${pids[@]}"; do kill -KILL "$p" 2>/dev/null; done
  ROBOT_ID=$REC_ID Tools/shm/shm remove >/dev/null 2>&1
  ROBOT_ID=$REP_ID Tools/shm/shm remove >/dev/null 2>&1
  if [ -n "${KEEP:-}" ]; then echo "# kept $dir"; else rm -rf "$dir"; fi
}
trap cleanup EXIT
n=0; fails=0
res() { n=$((n + 1)); if [ "$1" = 0 ]; then echo "ok $n - $2"; else fails=$((fails + 1)); echo "not ok $n - $2"; fi; }
now() { date +%s.%N; }

# this run's own ports: no other robot's GameController or team messages reach the behavior
ports() { export HRP_GC_PORT=$((40000 + $1 % 20000)) HRP_GC_RETURN_PORT=$((40001 + $1 % 20000)) HRP_TEAM_PORT=$((30000 + $1 % 20000)); }

# Waits until the DCM of robot $1 holds the lockstep clock (so that every process joins before tick 1).
wait_lockstep() {
  for _ in $(seq 1 200); do
    ROBOT_ID=$1 Tools/shm/shm dump sync 2>/dev/null | grep -Eq '^lockstep +i32 \[1\] +1$' && return 0
    sleep 0.05
  done
  return 1
}

# Starts the recorder (lockstep observer) and the Lua processes "$@" of robot $ID into $out, under $PLATFORM_LUA.
start_robot() {
  local out=$1 camera=$2; shift 2
  # one file (the Replay platform plays one; the 2-minute game takes ~550 MB with raw frames)
  build/bin/hrp_record --lockstep --camera "$camera" --file-mb 4000 --total-mb 4000 --dir "$out" --quiet \
    > "$out/record.out" 2>&1 &
  pids+=($!)
  for p in "$@"; do
    PLATFORM=Sim HRP_SITE="${SITE:-}" luajit "Player/$p/main.lua" > "$out/$p.out" 2>&1 &
    pids+=($!)
  done
}

stop_robot() {
  for p in "${pids[@]}"; do kill -TERM "$p" 2>/dev/null; done
  for p in "${pids[@]}"; do wait "$p" 2>/dev/null; done
  pids=()
}

# ---- 1. the game, recorded
export ROBOT_ID=$REC_ID
ports $REC_ID
Tools/shm/shm remove >/dev/null 2>&1
mkdir -p "$dir/rec"
t0=$(now)
build/bin/dcm_sim --lockstep-wait 4 --duration "$SECONDS_SIM" --seed 1 --quiet > "$dir/rec/dcm.out" 2>&1 &
dcm=$!
wait_lockstep $REC_ID
start_robot "$dir/rec" raw Motion Vision Behavior
wait $dcm
rc=$?
rec_wall=$(echo "$(now) - $t0" | bc)
stop_robot
log=$(ls "$dir"/rec/hrp-*.mcap 2>/dev/null | head -1)
nfiles=$(ls "$dir"/rec/hrp-*.mcap 2>/dev/null | wc -l)
echo "# recorded ${SECONDS_SIM} s of game in ${rec_wall} s: $(cat "$dir/rec/record.out")"
[ $rc -eq 0 ] && [ "$nfiles" = 1 ] && grep -q "dropped 0, missed ticks 0" "$dir/rec/record.out"
res $? "the sim plays ${SECONDS_SIM} s in lockstep, every tick recorded (none dropped or missed)"
if [ -z "$log" ]; then echo "1..$n"; exit 1; fi

# ---- 2. the replay: vision and behavior on the recording, recorded again
replay() {   # replay OUT [SITE]
  local out=$1
  export ROBOT_ID=$REP_ID
  ports $REP_ID
  Tools/shm/shm remove >/dev/null 2>&1
  mkdir -p "$out"
  local t0 rc
  t0=$(now)
  PLATFORM=Replay build/bin/dcm_replay --log "$log" --lockstep-wait 3 > "$out/dcm.out" 2>&1 &
  local dcm=$!
  wait_lockstep $REP_ID
  SITE=${2:-} start_robot "$out" off Vision Behavior
  wait $dcm
  rc=$?
  echo "$(echo "$(now) - $t0" | bc)" > "$out/wall"
  stop_robot
  sed 's/^/# /' "$out/dcm.out"
  return $rc
}
replay "$dir/rep"
rc=$?
rep_wall=$(cat "$dir/rep/wall")
res $rc "the Replay DCM serves the whole log in lockstep to vision and behavior (${rep_wall} s of wall time)"

# ---- 3. tick by tick, bit for bit
topics="/vision /world /game /team /motion"
out=$(python3 Tests/replay/compare_logs.py "$log" "$dir"/rep/hrp-*.mcap $topics)
rc=$?
echo "$out" | sed 's/^/# /'
ticks=$(echo "$out" | sed -n 's/^compare: ticks \([0-9]*\).*/\1/p')
[ $rc -eq 0 ] && [ "${ticks:-0}" -ge $((SECONDS_SIM * 125 - 2)) ]
res $? "the replay reproduces the recorded vision, world model, game and team blocks and the behavior's commands at every one of ${ticks:-0} ticks, bit for bit"

# ---- 4. a swapped process: vision with a changed detector setting
mkdir -p "$dir/site"
cp Config/site/*.lua "$dir/site/"
# a ball must fill 3/4 of its box (the default accepts the sim's round ball at a lower fill)
printf 'return {\n  lut = false,\n  ball = { min_fill = 0.75 },\n}\n' > "$dir/site/vision.lua"
replay "$dir/swap" "$dir/site"
out=$(python3 Tests/replay/compare_logs.py "$log" "$dir"/swap/hrp-*.mcap /vision /world)
echo "$out" | sed 's/^/# /'
count() {   # balls seen in a log's vision messages
  python3 -c "
import sys
from mcap.reader import make_reader
from mcap_ros2.decoder import DecoderFactory
r = make_reader(open(sys.argv[1], 'rb'), decoder_factories=[DecoderFactory()])
print(sum(o.ball_detected for _, _, _, o in r.iter_decoded_messages(topics=['/vision'])))" "$1"
}
seen=$(count "$log"); seen_swap=$(count "$dir"/swap/hrp-*.mcap)
echo "# ball detections: recorded $seen, replayed through the changed vision $seen_swap"
vm=$(echo "$out" | sed -n 's/^\/vision: .* mismatches \([0-9]*\).*/\1/p')
wm=$(echo "$out" | sed -n 's/^\/world: .* mismatches \([0-9]*\).*/\1/p')
[ "${vm:-0}" -gt 0 ] && [ "${wm:-0}" -gt 0 ] && [ "$seen_swap" != "$seen" ]
res $? "a swapped vision (ball.min_fill 0.75) on the same log: other detections ($seen_swap balls, not $seen) and another world model"
echo "# wall time: record ${rec_wall} s, replay ${rep_wall} s, swapped replay $(cat "$dir/swap/wall") s"
echo "1..$n"
[ "$fails" -eq 0 ]
