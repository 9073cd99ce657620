# Shared by the hardware-in-the-loop scenarios (Tests/hil/*_test.sh): the sim DCM's robot SIM_ID,
# the hardware DCM and the motion process on OP_ID = SIM_ID + 1, Tests/hil/hil_walk.lua measuring.
# Sourced after `cd` to the root and `source Run/env.sh`; ROBOT set by the caller.
LOGDIR="$HRP_ROOT/build/test-logs/hil"
mkdir -p "$LOGDIR"
SIM_ID=${ROBOT_ID:-9450}
OP_ID=$((SIM_ID + 1))
T=$(mktemp -d)
PIDS=()
n=0 fails=0
ok() { n=$((n + 1)); if [ "$1" = 0 ]; then echo "ok $n - $2"; else echo "not ok $n - $2"; fails=$((fails + 1)); fi; }
stop_all() {
  for p in "${PIDS[@]}"; do kill -TERM "$p" 2>/dev/null; done
  for p in "${PIDS[@]}"; do wait "$p" 2>/dev/null; done
  PIDS=()
  Tools/shm/shm --robot "$SIM_ID" remove >/dev/null 2>&1
  Tools/shm/shm --robot "$OP_ID" remove >/dev/null 2>&1
}
trap 'stop_all; rm -rf "$T"' EXIT
# wait_log FILE PATTERN: up to 20 s
wait_log() { for _ in $(seq 200); do grep -q "$2" "$1" 2>/dev/null && return 0; sleep 0.1; done; return 1; }
# measure NAME PLATFORM ID SECONDS VX|stand [STAND]: hil_walk.lua against robot ID, truth from SIM_ID
# (STAND s standing before the walk); its TAP renumbered into this script's, the tracking figures
# "RMS MAX" into $T/NAME.track
measure() {
  PLATFORM=$2 ROBOT_ID=$3 SIM_ID=$SIM_ID timeout 300 ./run_repl Tests/hil/hil_walk.lua "$4" "$5" ${6:+"$6"} \
    >"$LOGDIR/$1.log" 2>&1
  while IFS= read -r line; do
    if [[ $line =~ ^(not\ ok|ok)\ [0-9]+\ -\ (.*)$ ]]; then
      ok "$([ "${BASH_REMATCH[1]}" = ok ]; echo $?)" "$1: ${BASH_REMATCH[2]}"
    elif [[ $line == \#* ]]; then echo "$line"; fi
  done <"$LOGDIR/$1.log"
  grep -q '^not ok' "$LOGDIR/$1.log" && tail -n 5 "$LOGDIR/$1.log" | sed 's/^/#   /'
  awk '/^tracking /{print $2, $3}' "$LOGDIR/$1.log" >"$T/$1.track"
}
# start_sim NAME: the sim DCM (real time, no camera) serving SIM_ID; at SCHED_FIFO where allowed, as
# the hardware DCMs and the emulators run (rt_priority, --realtime): on a loaded machine a sim that
# falls behind the wall clock gets the bus's commands faster than its physics moves
start_sim() {
  Tools/shm/shm --robot "$SIM_ID" remove >/dev/null 2>&1
  local rt=()
  chrt -f 20 true 2>/dev/null && rt=(chrt -f 20)
  PLATFORM=Sim ROBOT_ID=$SIM_ID "${rt[@]}" ./run_dcm --no-camera --quiet >"$LOGDIR/sim_$1.log" 2>&1 &
  PIDS+=($!)
  for _ in $(seq 100); do [ -e /dev/shm/hrp."$SIM_ID".dcm.sensor ] && break; sleep 0.1; done
  sleep 0.5
}
# start_motion PLATFORM ID NAME: the motion process of robot ID, at SCHED_FIFO below the DCMs where
# allowed (in real time on a loaded machine a motion process that misses ticks stumbles)
start_motion() {
  local rt=()
  chrt -f 10 true 2>/dev/null && rt=(chrt -f 10)
  PLATFORM=$1 ROBOT_ID=$2 "${rt[@]}" ./run_main --quiet --no-restart motion >"$LOGDIR/main_$3.log" 2>&1 &
  PIDS+=($!)
  wait_log "$LOGDIR/main_$3.log" 'motion started'
}
