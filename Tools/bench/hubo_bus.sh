#!/usr/bin/env bash
# The Hubo DCM's buses at 200 Hz against the emulated Hubo2+ boards and their 1 Mbit/s timing
# model (exact bits per frame, stuff bits included), through the fake SocketCAN (prints figures,
# never fails on time): frames and bits per cycle on each bus, bus load in % of 1 Mbit/s, the
# cycle's jitter p50 / p99 / max, missed cycles, board timeouts and skipped frames; clean, with 1%
# of the boards' frames corrupted, and with a dead board.
#   Tools/bench/hubo_bus.sh [SECONDS per run, default 5]
set -u
cd "$(dirname "$0")/../.."
source Tests/hubo/tree.sh
export PLATFORM=Hubo ROBOT=hubo2plus
export ROBOT_ID="${ROBOT_ID:-8650}"
SECS=${1:-5}
source Tests/dcm_emu_lib.sh
hubo_tree "$T/root"
mkdir "$T/bus"
export FAKECAN_DIR=$T/bus
cd "$T/root"

stats() {
  ./run_repl -e 'local s = require("shm").open("dcm.stats")
    local t, d = 0, 0
    for k = 0, 31 do t = t + s.board_timeouts[k]; d = d + s.board_dead[k] end
    print(string.format("%.1f %.1f %.0f %.0f %.1f %.1f %.0f %.0f %.0f %.1f %d %d %d %d", s.bus_frames[0], s.bus_frames[1],
      s.bus_bits[0], s.bus_bits[1], s.bus_load[0], s.bus_load[1], s.jitter_p50[0] * 1e6, s.jitter_p99[0] * 1e6,
      s.jitter_max[0] * 1e6, s.rate[0], s.cycles[0], s.missed_cycles[0], t, s.rx_errors[0]) .. " " .. d)' 2>/dev/null | tail -1
}

run() {   # run LABEL EMU_ARGS...
  local label=$1; shift
  rm -f /dev/shm/hrp."$ROBOT_ID".*
  HUBO_FAKE_CAN=1 Platforms/Hubo/emulator/hubo_emulator --quiet --realtime "$@" 2>"$T/emu.log" & EMU=$!
  for _ in $(seq 100); do grep -q ready "$T/emu.log" 2>/dev/null && break; sleep 0.05; done
  HUBO_FAKE_CAN=1 ./run_dcm --cycles $((SECS * 200)) 2>"$T/dcm.log" & DCM=$!
  sleep "$SECS"
  # read while it runs (the statistics window of the last second), then let it finish
  read -r f0 f1 b0 b1 l0 l1 p50 p99 jmax rate c missed to rx dead < <(stats)
  wait "$DCM"; DCM=""
  kill "$EMU"; wait "$EMU" 2>/dev/null; EMU=""
  echo "$label:"
  printf '  bus 1 (legs, waist, foot F/T, IMU): %5s frames %5s bits per cycle, load %5s %%\n' "$f0" "$b0" "$l0"
  printf '  bus 2 (arms, hand F/T, power):      %5s frames %5s bits per cycle, load %5s %%\n' "$f1" "$b1" "$l1"
  printf '  rate %s Hz, jitter p50 %s us, p99 %s us, max %s us; %s cycles, %s missed\n' "$rate" "$p50" "$p99" "$jmax" "$c" "$missed"
  printf '  %s board timeouts, %s frames skipped, %s board(s) dead\n' "$to" "$rx" "$dead"
}

echo "per 200 Hz cycle: references to every motor board, an encoder request and reply each, F/T and IMU"
echo "requests and replies, a status and a current request in turn (HuboCan's budget: ~46 frames of"
echo "108 bits per bus and cycle at 1 Mbit/s)"
run "clean"
run "1% of the boards' frames corrupted" --corrupt 0.01 --seed 7
run "a dead board (JMC8, bus 2)" --dead JMC8
