#!/usr/bin/env bash
# Wire efficiency of the OP DCM on the virtual servo bus (prints figures, never fails on time):
#   bytes on the wire per cycle for 20 servos + IMU + buttons, protocol 1.0 (DARwIn-OP) and 2.0
#   (OP3), the bus-limited cycle rate at 1 Mbps (10 microseconds a byte) that follows; then the
#   DCM at 125 Hz against the emulator's timing model (wire time + return delay), with its rate,
#   jitter and missed cycles; then 1% corrupt answers.
#   Tools/bench/dxl_wire.sh [SECONDS per run, default 4]
set -u
cd "$(dirname "$0")/../.."
source Run/env.sh
export PLATFORM=OP
export ROBOT_ID="${ROBOT_ID:-8600}"
SECS=${1:-4}
source Tests/dcm_emu_lib.sh

stats() {
  ./run_repl -e 'local s = require("shm").open("dcm.stats")
    local t, d = 0, 0
    for j = 0, 19 do t = t + s.servo_timeouts[j]; d = d + s.servo_dead[j] end
    print(string.format("%.1f %.1f %.1f %.1f %d %d %d %d %d", s.rate[0], s.bytes_per_cycle[0],
      s.jitter_p99[0] * 1e6, s.jitter_max[0] * 1e6, s.cycles[0], s.missed_cycles[0], s.rx_errors[0], t, d))' 2>/dev/null | tail -1
}

run() {   # run LABEL ROBOT EMU_ARGS...
  local label=$1 robot=$2; shift 2
  rm -f /dev/shm/hrp."$ROBOT_ID".*
  build/bin/dxl_emulator --link "$T/dxl" --quiet --realtime "$@" 2>/dev/null & EMU=$!
  for _ in $(seq 100); do [ -e "$T/dxl" ] && break; sleep 0.05; done
  local cycles=$((SECS * 125))
  ROBOT=$robot ./run_dcm --port "$T/dxl" --cycles "$cycles" 2>"$T/dcm.log" & DCM=$!
  sleep "$SECS"
  # read while it runs (the window of the last second), then let it finish
  read -r rate bpc p99 jmax c missed rx to dead < <(stats)
  wait "$DCM"; DCM=""
  kill "$EMU"; wait "$EMU" 2>/dev/null; EMU=""
  local plan
  plan=$(grep -o 'wire per cycle: [0-9]* bytes.*' "$T/dcm.log" | sed 's/wire per cycle: //')
  printf '%-34s planned %s\n%-34s measured %s B/cycle | DCM %s Hz, jitter p99 %s us, max %s us, missed %s, rx_errors %s, timeouts %s\n' \
    "$label" "$plan" "" "$bpc" "$rate" "$p99" "$jmax" "$missed" "$rx" "$to"
}

echo "20 servos + IMU + buttons per cycle at 1 Mbps (goal: <= 340 B/cycle, ~290 Hz, in protocol 1.0)"
echo "machine load: $(cut -d' ' -f1-3 /proc/loadavg) on $(nproc) cores (the emulator and the DCM are ordinary processes)"
run "DARwIn-OP protocol 1.0"            darwin --protocol 1
run "OP3 protocol 2.0"                  op3    --protocol 2
run "DARwIn-OP 1.0, timing model"       darwin --protocol 1 --timing
run "OP3 2.0, timing model"             op3    --protocol 2 --timing
run "DARwIn-OP 1.0, timing, 1% corrupt" darwin --protocol 1 --timing --corrupt 0.01 --seed 5
