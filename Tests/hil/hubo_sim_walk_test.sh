#!/usr/bin/env bash
# Hardware in the loop, CAN, walking: the unchanged Hubo DCM (PLATFORM=Hubo, robot ROBOT_ID+1, on
# the fake SocketCAN of Platforms/Hubo/tests) keeps the simulated Hubo2+ (the sim DCM's robot
# ROBOT_ID, real time) standing HIL_STAND s and then walking forward HIL_SECONDS s at HIL_VX m/s
# through Platforms/Hubo/emulator/hubo_emulator --sim-id (no fall, from the sim's truth), the balance feedback on the
# feet's F/T boards on (Player/Motion/balance.lua), and the F/T boards read back the simulated
# weight. The same on the sim DCM directly first, for the leg joints' tracking error (command vs
# simulated position, RMS per joint group) and the ZMP error of both, side by side.
# Real time: the emulator and dcm_hubo pace themselves on the wall clock (no lockstep through the
# bus); measured 5 of 5 runs without a fall (Platforms/Hubo/README.md).
#   [ROBOT_ID=N] [HIL_STAND=30] [HIL_SECONDS=10] [HIL_VX=0.25] Tests/hil/hubo_sim_walk_test.sh
set -u
cd "$(dirname "$0")/../.."
source Run/env.sh
export ROBOT=hubo2plus
source Tests/hil/lib.sh
STAND=${HIL_STAND:-30}
SECS=${HIL_SECONDS:-10}
VX=${HIL_VX:-0.25}

# ---- the sim DCM directly (real time)
start_sim direct
start_motion Sim "$SIM_ID" direct
measure direct Sim "$SIM_ID" "$SECS" "$VX" "$STAND"
stop_all

# ---- through the buses: sim DCM <- hubo_emulator --sim-id <- dcm_hubo <- motion
mkdir -p "$T/bus"
export FAKECAN_DIR=$T/bus
start_sim hil
HUBO_FAKE_CAN=1 Platforms/Hubo/emulator/hubo_emulator --sim-id "$SIM_ID" --realtime >"$LOGDIR/hubo_emu.log" 2>&1 &
PIDS+=($!)
wait_log "$LOGDIR/hubo_emu.log" ready
ok $? "hubo_emulator --sim-id serves the simulated Hubo2+'s boards"
Tools/shm/shm --robot "$OP_ID" remove >/dev/null 2>&1
HUBO_FAKE_CAN=1 PLATFORM=Hubo ROBOT_ID=$OP_ID ./run_dcm --quiet \
  >"$LOGDIR/dcm_hubo.log" 2>&1 &
PIDS+=($!)
start_motion Hubo "$OP_ID" hil
measure hil Hubo "$OP_ID" "$SECS" "$VX" "$STAND"
# the feet's F/T boards carry the simulated robot's weight (Fz of both feet, through the bus; the
# robot stopped into stance by hil_walk.lua)
sleep 3
fz=$(PLATFORM=Hubo ROBOT_ID=$OP_ID ./run_repl -e 'local s = require("shm").open("dcm.sensor"); print(s.ft[2] + s.ft[8])' 2>&1 | tail -1)
echo "# F/T boards through the bus: feet Fz sum $fz N (the Hubo2+ weighs 441 N, 418 N above the sensors)"
ok "$(awk -v f="$fz" 'BEGIN{exit !(f > 380 && f < 460)}'; echo $?)" "the feet's F/T boards read the simulated weight ($fz N)"
stop_all
for ph in stand walk; do
  echo "# $ph, leg tracking RMS per joint group (rad); ZMP error:"
  for r in direct:"sim DCM directly:              " hil:"dcm_hubo through hubo_emulator:"; do
    echo "#   ${r#*:} $(sed -n "s/^# $ph leg tracking RMS per joint group (rad): //p" "$LOGDIR/${r%%:*}.log");" \
      "$(sed -n "s/^# $ph ZMP error (the feet's F\/T against the walk's reference) //p" "$LOGDIR/${r%%:*}.log")"
  done
done
[ $fails -eq 0 ]
