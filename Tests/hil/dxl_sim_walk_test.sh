#!/usr/bin/env bash
# Hardware in the loop, Dynamixel: the unchanged OP DCM (PLATFORM=OP, robot ROBOT_ID+1) drives the
# simulated OP3 (the sim DCM's robot ROBOT_ID, real time) through Run/dxl_emulator --sim-id: the
# motion process walks it 30 s at 0.2 m/s without a fall (from the sim's truth). The same walk on the
# sim DCM directly first, for the leg joints' tracking error (command vs simulated position) of both.
#   [ROBOT_ID=N] [HIL_SECONDS=30] Tests/hil/dxl_sim_walk_test.sh
set -u
cd "$(dirname "$0")/../.."
source Run/env.sh
export ROBOT=op3
LOGDIR="$HRP_ROOT/build/test-logs/hil"
mkdir -p "$LOGDIR"
SIM_ID=${ROBOT_ID:-9450}
OP_ID=$((SIM_ID + 1))
SECS=${HIL_SECONDS:-30}
T=$(mktemp -d)
PIDS=()
n=0 fails=0
ok() { n=$((n + 1)); if [ "$1" = 0 ]; then echo "ok $n - $2"; else echo "not ok $n - $2"; fails=$((fails + 1)); fi; }
stop_all() {
  for p in "${PIDS[@]}"; do kill -TERM "$p" 2>/dev/null; done
  for p in "${PIDS[@]}"; do wait "$p" 2>/dev/null; done
  PIDS=()
  Run/shm --robot "$SIM_ID" remove >/dev/null 2>&1
  Run/shm --robot "$OP_ID" remove >/dev/null 2>&1
}
trap 'stop_all; rm -rf "$T"' EXIT
# wait_log FILE PATTERN: up to 20 s
wait_log() { for _ in $(seq 200); do grep -q "$2" "$1" 2>/dev/null && return 0; sleep 0.1; done; return 1; }
# walk NAME ID: the walk script against robot ID (motion's), the truth from SIM_ID; TAP renumbered
walk() {
  ROBOT_ID=$2 SIM_ID=$SIM_ID timeout 300 ./run_repl Tests/hil/hil_walk.lua "$SECS" 0.2 >"$LOGDIR/$1.log" 2>&1
  while IFS= read -r line; do
    if [[ $line =~ ^(not\ ok|ok)\ [0-9]+\ -\ (.*)$ ]]; then
      ok "$([ "${BASH_REMATCH[1]}" = ok ]; echo $?)" "$1: ${BASH_REMATCH[2]}"
    elif [[ $line == \#* ]]; then echo "$line"; fi
  done <"$LOGDIR/$1.log"
  grep -q '^ok .*without a fall' "$LOGDIR/$1.log" || tail -n 5 "$LOGDIR/$1.log" | sed 's/^/#   /'
  awk '/^tracking /{print $2, $3}' "$LOGDIR/$1.log" >"$T/$1.track"
}
start_sim() {
  Run/shm --robot "$SIM_ID" remove >/dev/null 2>&1
  PLATFORM=Sim ROBOT_ID=$SIM_ID ./run_dcm --no-camera --quiet >"$LOGDIR/sim_$1.log" 2>&1 &
  PIDS+=($!)
  for _ in $(seq 100); do [ -e /dev/shm/hrp."$SIM_ID".dcm.sensor ] && break; sleep 0.1; done
  sleep 0.5
}
start_motion() {
  PLATFORM=$1 ROBOT_ID=$2 ./run_main --quiet --no-restart motion >"$LOGDIR/main_$3.log" 2>&1 &
  PIDS+=($!)
  wait_log "$LOGDIR/main_$3.log" 'motion started'
}

# ---- the sim DCM directly (real time)
start_sim direct
start_motion Sim "$SIM_ID" direct
walk direct "$SIM_ID"
read -r d_rms d_max <"$T/direct.track"
stop_all

# ---- through the bus: sim DCM <- dxl_emulator --sim-id <- dcm_op <- motion
start_sim hil
build/bin/dxl_emulator --link "$T/dxl" --sim-id "$SIM_ID" --realtime --quiet >"$LOGDIR/emu.log" 2>&1 &
PIDS+=($!)
for _ in $(seq 100); do [ -e "$T/dxl" ] && break; sleep 0.05; done
ok "$([ -e "$T/dxl" ]; echo $?)" "dxl_emulator --sim-id serves the simulated OP3's bus"
Run/shm --robot "$OP_ID" remove >/dev/null 2>&1
PLATFORM=OP ROBOT_ID=$OP_ID ./run_dcm --port "$T/dxl" --quiet >"$LOGDIR/dcm_op.log" 2>&1 &
PIDS+=($!)
start_motion OP "$OP_ID" hil
walk hil "$OP_ID"
read -r h_rms h_max <"$T/hil.track"
echo "# leg tracking error, command vs simulated position (RMS / max, rad): sim DCM ${d_rms:-?} / ${d_max:-?}," \
  "dcm_op through dxl_emulator --sim-id ${h_rms:-?} / ${h_max:-?}"
stop_all
[ $fails -eq 0 ]
