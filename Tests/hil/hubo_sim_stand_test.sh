#!/usr/bin/env bash
# Hardware in the loop, CAN: the unchanged Hubo DCM (PLATFORM=Hubo, robot ROBOT_ID+1, on the fake
# SocketCAN of Platforms/Hubo/tests) keeps the simulated Hubo2+ (the sim DCM's robot ROBOT_ID, real
# time) standing 30 s through Run/hubo_emulator --sim-id (from the sim's truth), and the F/T boards
# read back the simulated feet. The same stance on the sim DCM directly first, for the leg joints'
# tracking error (command vs simulated position) of both.
#   [ROBOT_ID=N] [HIL_SECONDS=30] Tests/hil/hubo_sim_stand_test.sh
set -u
cd "$(dirname "$0")/../.."
source Run/env.sh
export ROBOT=hubo2plus
source Tests/hil/lib.sh
SECS=${HIL_SECONDS:-30}

# ---- the sim DCM directly (real time)
start_sim direct
start_motion Sim "$SIM_ID" direct
measure direct Sim "$SIM_ID" "$SECS" stand
read -r d_rms d_max <"$T/direct.track"
stop_all

# ---- through the buses: sim DCM <- hubo_emulator --sim-id <- dcm_hubo <- motion
mkdir -p "$T/bus"
export FAKECAN_DIR=$T/bus
start_sim hil
HUBO_FAKE_CAN=1 Run/hubo_emulator --sim-id "$SIM_ID" --realtime >"$LOGDIR/hubo_emu.log" 2>&1 &
PIDS+=($!)
wait_log "$LOGDIR/hubo_emu.log" ready
ok $? "hubo_emulator --sim-id serves the simulated Hubo2+'s boards"
Run/shm --robot "$OP_ID" remove >/dev/null 2>&1
LD_PRELOAD=$HRP_ROOT/build/testlib/libfakecan.so PLATFORM=Hubo ROBOT_ID=$OP_ID ./run_dcm --quiet \
  >"$LOGDIR/dcm_hubo.log" 2>&1 &
PIDS+=($!)
start_motion Hubo "$OP_ID" hil
measure hil Hubo "$OP_ID" "$SECS" stand
read -r h_rms h_max <"$T/hil.track"
# the feet's F/T boards carry the simulated robot's weight (Fz of both feet, through the bus)
fz=$(PLATFORM=Hubo ROBOT_ID=$OP_ID ./run_repl -e 'local s = require("shm").open("dcm.sensor"); print(s.ft[2] + s.ft[8])' 2>&1 | tail -1)
echo "# F/T boards through the bus: feet Fz sum $fz N (the Hubo2+ weighs 441 N, 418 N above the sensors)"
ok "$(awk -v f="$fz" 'BEGIN{exit !(f > 380 && f < 460)}'; echo $?)" "the feet's F/T boards read the simulated weight ($fz N)"
echo "# leg tracking error, command vs simulated position (RMS / max, rad): sim DCM ${d_rms:-?} / ${d_max:-?}," \
  "dcm_hubo through hubo_emulator --sim-id ${h_rms:-?} / ${h_max:-?}"
stop_all
[ $fails -eq 0 ]
