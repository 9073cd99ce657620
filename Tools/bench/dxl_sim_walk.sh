#!/usr/bin/env bash
# Hardware in the loop, Dynamixel: the unchanged OP DCM (PLATFORM=OP, robot ROBOT_ID+1) drives the
# simulated OP3 (the sim DCM's robot ROBOT_ID, real time) through Platforms/OP/emulator/dxl_emulator --sim-id: the
# motion process walks it 30 s at 0.2 m/s without a fall (from the sim's truth). The same walk on the
# sim DCM directly first, for the leg joints' tracking error (command vs simulated position) of both.
#   [ROBOT_ID=N] [HIL_SECONDS=30] Tools/bench/dxl_sim_walk.sh
# In `make bench` (hil_walk_op3), not `make test`: in real time the walk through the bus lasted the 30 s
# in 3 of 5 runs (and directly on the sim in 4 of 5): the real-time walk's margin is thin on a loaded
# machine, so this prints its figures and outcome rather than gating CI.
set -u
cd "$(dirname "$0")/../.."
source Run/env.sh
export ROBOT=op3
source Tests/hil/lib.sh
SECS=${HIL_SECONDS:-30}

# ---- the sim DCM directly (real time)
start_sim direct
start_motion Sim "$SIM_ID" direct
measure direct Sim "$SIM_ID" "$SECS" 0.2
read -r d_rms d_max <"$T/direct.track"
stop_all

# ---- through the bus: sim DCM <- dxl_emulator --sim-id <- dcm_op <- motion
start_sim hil
build/bin/dxl_emulator --link "$T/dxl" --sim-id "$SIM_ID" --realtime --quiet >"$LOGDIR/emu.log" 2>&1 &
PIDS+=($!)
for _ in $(seq 100); do [ -e "$T/dxl" ] && break; sleep 0.05; done
ok "$([ -e "$T/dxl" ]; echo $?)" "dxl_emulator --sim-id serves the simulated OP3's bus"
Tools/shm/shm --robot "$OP_ID" remove >/dev/null 2>&1
PLATFORM=OP ROBOT_ID=$OP_ID ./run_dcm --port "$T/dxl" --quiet >"$LOGDIR/dcm_op.log" 2>&1 &
PIDS+=($!)
start_motion OP "$OP_ID" hil
measure hil OP "$OP_ID" "$SECS" 0.2
read -r h_rms h_max <"$T/hil.track"
echo "# leg tracking error, command vs simulated position (RMS / max, rad): sim DCM ${d_rms:-?} / ${d_max:-?}," \
  "dcm_op through dxl_emulator --sim-id ${h_rms:-?} / ${h_max:-?}"
stop_all
[ $fails -eq 0 ]
