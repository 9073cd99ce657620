#!/usr/bin/env bash
# The Hubo DCM drives the emulated Hubo2+ boards (Platforms/Hubo/emulator/hubo_emulator) over SocketCAN, through the
# fake SocketCAN of the tests (this kernel has no AF_CAN; HUBO_FAKE_CAN=1: the DCM's test build and the
# emulator, each with the fake linked in, so make sanitize runs the DCM under ASan), end to end:
#   bring-up (FETs and controllers on); a command from ./run_repl becomes the board's reference in
#   counts and comes back as its encoder; F/T, IMU and the power board read back; a reference jump
#   is spread over cycles at the joint's speed limit; 1% corrupted frames: the DCM keeps its rate
#   and counts them; a dead board is reported, its joints held, the others go on, and it rejoins
#   without a jump; a board's fault bits are counted; a bus that goes away is reported and reopened.
set -u
cd "${HRP_ROOT:-$(dirname "$0")/../..}"
source Tests/hubo/tree.sh
export ROBOT_ID=${ROBOT_ID:-9450} PLATFORM=Hubo ROBOT=hubo2plus
source Tests/dcm_emu_lib.sh
hubo_fake_bus
# emu_board NAME: "ref0 ref1 enc0 enc1 fet ctrl home dead" from the emulator's stats
emu_board() { emu_stats; grep "^board $1 " "$T/emu.out" | awk '{print $8, $9, $11, $12, $14, $16, $18, $20}'; }
emu_line() { emu_stats; grep "^$1" "$T/emu.out"; }
# joint indices by name (J.RSP), whatever the body's joint order
stats() { repl "local s = require('shm').open('dcm.stats'); local J = {}
  for i, name in ipairs(require('Config').load('robot').joints) do J[name] = i - 1 end; print($1)"; }

# ---------------------------------------------------------------- bring-up, command, encoder
rm -f /dev/shm/hrp."$ROBOT_ID".*
start_emu
start_dcm
wait_for 'require("shm").open("dcm.stats").cycles[0] > 50'; ok $? "the DCM cycles against the emulated boards"
s=$(emu_board JMC2)
ok $([ "$(echo "$s" | awk '{print $5, $6, $7}')" = "1 1 6" ]; echo $?) "bring-up: JMC2's FETs and controller on, homed ($s)"
repl 'Body.set_command("RKN", 0.5); Body.set_command("LSP", -0.3)' >/dev/null
# RKN: JMC2 channel 0, 101859.16 counts/rad: 0.5 rad -> 50929 (truncated toward zero)
for _ in $(seq 50); do s=$(emu_board JMC2); [ "${s%% *}" = 50929 ] && break; sleep 0.1; done
ok $([ "${s%% *}" = 50929 ]; echo $?) "REPL command RKN 0.5 rad becomes JMC2's reference 50929 counts ($s)"
# LSP: JMC10 channel 0, 11:16 x100 x4000 = 92599.4 counts/rad: -0.3 rad -> -27779
for _ in $(seq 50); do s=$(emu_board JMC10); [ "${s%% *}" = -27779 ] && break; sleep 0.1; done
ok $([ "${s%% *}" = -27779 ]; echo $?) "LSP -0.3 rad becomes JMC10's reference -27779 counts on bus 2 ($s)"
wait_for 'math.abs(Body.get_position("RKN") - 0.5) < 0.001 and math.abs(Body.get_position("LSP") + 0.3) < 0.001'
ok $? "the boards' encoders come back as the joint positions"
limited=$(stats 's.ref_limited[0]')
ok $([ "${limited:-0}" -gt 5 ]; echo $?) "the 0.5 rad step went out over several cycles at RKN's speed limit ($limited joint-cycles held back)"

# ---------------------------------------------------------------- NaN and compliance
repl 'local a = require("shm").open("dcm.actuator"); local J = {}
  for i, name in ipairs(require("Config").load("robot").joints) do J[name] = i - 1 end
  a:write(function(x) x.command[J.RKN] = 0/0 end)' >/dev/null
wait_for 'require("shm").open("dcm.stats").nan_commands[0] > 0'; ok $? "a NaN command is refused and counted"
sleep 0.3
s=$(emu_board JMC2)
ok $([ "${s%% *}" = 50929 ]; echo $?) "NaN never reaches the board: JMC2 keeps its reference ($s)"
repl 'Body.set_command("RKN", 0.5)' >/dev/null
# LSR (JMC10 channel 1) held at 0; a hand moves it to 10000 counts: stiff, the reference stays at
# the command and the board pulls it back; compliant (hardness 0), the reference follows the joint
echo "move JMC10 1 10000" >&3
sleep 0.3
s=$(emu_board JMC10)
ok $([ "$(echo "$s" | awk '{print $2}')" = 0 ]; echo $?) "hardness 1: LSR's reference stays at the command when moved by hand ($s)"
repl 'local a = require("shm").open("dcm.actuator"); local J = {}
  for i, name in ipairs(require("Config").load("robot").joints) do J[name] = i - 1 end
  a:write(function(x) x.hardness[J.LSR] = 0 end)' >/dev/null
sleep 0.2
echo "move JMC10 1 10000" >&3
# the hand lets go at once, so board and reference meet between the command and 10000
for _ in $(seq 30); do s=$(emu_board JMC10); [ "$(echo "$s" | awk '{print ($2 == $4 && $2 > 1000)}')" = 1 ] && break; sleep 0.1; done
ok $([ "$(echo "$s" | awk '{print ($2 == $4 && $2 > 1000)}')" = 1 ]; echo $?) "hardness 0: LSR's reference follows its position where the hand moved it (compliant) ($s)"
repl 'local a = require("shm").open("dcm.actuator"); local J = {}
  for i, name in ipairs(require("Config").load("robot").joints) do J[name] = i - 1 end
  a:write(function(x) x.hardness[J.LSR] = 1; x.command[J.LSR] = 0 end)' >/dev/null

# ---------------------------------------------------------------- sensors
echo "ft LFFT 1.5 -2.0 300" >&3; echo "ft RHFT 0.5 0.25 -12" >&3
echo "imu 0.05 -0.1 0.2 -0.3" >&3; echo "power 47.5 3.2 152" >&3
wait_for 'math.abs(require("shm").open("dcm.sensor").foot_force[0] - 300) < 0.2'
ok $? "left foot F/T Fz reads back as foot_force[0]"
got=$(repl 'local s = require("shm").open("dcm.sensor"); print(string.format("%.2f %.2f %.1f %.2f %.2f %.1f", s.ft[3], s.ft[4], s.ft[2], s.ft[21], s.ft[22], s.ft[20]))')
ok $([ "$got" = "1.50 -2.00 300.0 0.50 0.25 -12.0" ]; echo $?) "F/T Mx My Fz of the left foot and right hand ($got)"
got=$(repl 'local s = require("shm").open("dcm.sensor"); print(string.format("%.3f %.3f %.3f %.3f %.1f", s.angle[0], s.angle[1], s.gyro[0], s.gyro[1], s.battery[0]))')
ok $([ "$got" = "0.050 -0.100 0.200 -0.300 47.5" ]; echo $?) "IMU angles and rates, power board voltage ($got)"
# the second statistics window (1 s each): the first holds the startup hold without references
wait_for 'require("shm").open("dcm.stats").cycles[0] > 420'
read -r f0 f1 b0 b1 l0 l1 < <(stats 'string.format("%.1f %.1f %.0f %.0f %.1f %.1f", s.bus_frames[0], s.bus_frames[1], s.bus_bits[0], s.bus_bits[1], s.bus_load[0], s.bus_load[1])')
echo "# per 200 Hz cycle: bus 1 $f0 frames $b0 bits ($l0 %), bus 2 $f1 frames $b1 bits ($l1 %)"
ok $(awk -v a="$f0" -v b="$l0" 'BEGIN{exit !(a >= 30 && a <= 46 && b > 50 && b < 100)}'; echo $?) "bus 1: 30-46 frames per cycle, load below 100 % ($f0 frames, $l0 %)"

# ---------------------------------------------------------------- a board with a fault
echo "error JMC5 4 0" >&3
wait_for 'require("shm").open("dcm.stats").board_faults[5] > 0'; ok $? "JMC5's big-error flag is counted (board_faults)"
echo "error JMC5 0 0" >&3

# ---------------------------------------------------------------- a dead board
echo "dead JMC8" >&3
wait_for 'require("shm").open("dcm.stats").board_dead[12] == 1'; ok $? "JMC8 stops answering: marked dead"
got=$(stats 's.servo_dead[J.RSP] + s.servo_dead[J.RSR] .. " " .. s.servo_dead[J.RSY] + s.servo_dead[J.RHP] + s.servo_dead[J.WST]')
ok $([ "$got" = "2 0" ]; echo $?) "its joints RSP RSR are reported dead, RSY RHP WST are not ($got)"
repl 'Body.set_command("RSP", 0.4); Body.set_command("RSY", 0.2)' >/dev/null
sleep 0.5
s8=$(emu_board JMC8); s9=$(emu_board JMC9)
# RSY: JMC9 channel 0, 63661.98 counts/rad: 0.2 rad -> 12732
ok $([ "${s8%% *}" = 0 ] && [ "${s9%% *}" = 12732 ]; echo $?) "no reference reaches the dead board; the others go on (JMC8 $s8, JMC9 $s9)"
grep -q "board JMC8 (0x08, bus 2) stopped answering: joints RSP RSR held" "$T/dcm.log"; ok $? "the log names the board and its joints"
echo "alive JMC8" >&3
wait_for 'require("shm").open("dcm.stats").board_dead[12] == 0'; ok $? "it answers again: alive"
for _ in $(seq 50); do s=$(emu_board JMC8); [ "${s%% *}" = 37039 ] && break; sleep 0.1; done
ok $([ "${s%% *}" = 37039 ]; echo $?) "references resume toward the command: RSP 0.4 rad = 37039 counts ($s)"
stop_dcm

# ---------------------------------------------------------------- 1% corrupted frames
stop_emu
fresh_run
start_emu --corrupt 0.01 --seed 5
dcm_to_end --cycles 1000
corrupted=$(emu_line totals | awk '{print $9}')
read -r cycles missed rate rx to < <(stats 'string.format("%d %d %.1f %d %d", s.cycles[0], s.missed_cycles[0], s.rate[0], s.rx_errors[0], (function() local t = 0 for k = 0, 31 do t = t + s.board_timeouts[k] end return t end)())')
echo "# 1000 cycles, 1% corrupt: emulator corrupted $corrupted frames; DCM: rate $rate Hz, $missed missed cycles, rx_errors $rx, board timeouts $to"
ok $([ "$cycles" = 1000 ] && awk -v r="$rate" 'BEGIN{exit !(r > 190 && r < 210)}'; echo $?) "with 1% corrupted frames the DCM keeps its rate ($cycles cycles, $rate Hz)"
# the DCM's closing lines give the classes per bus: corrupt (wrong DLC, error frames) and
# misaddressed are exactly the emulator's damage; unexpected ones are replies later than two cycles
classes=$(grep "stopped after 1000 cycles" "$T/dcm.log" | sed -E 's/.*; ([0-9]+) corrupt, ([0-9]+) misaddressed, ([0-9]+) unexpected.*/\1 \2 \3/' |
  awk '{c += $1 + $2; u += $3} END {print c + 0, u + 0}')
ok $([ "${classes% *}" = "${corrupted:-x}" ]; echo $?) "every corrupted frame is counted once as corrupt or misaddressed (${classes% *} of $corrupted; ${classes#* } unexpected late replies; rx_errors $rx)"
# a corrupted reply costs at most its own answer (a bit error is sent again: none; a wrong DLC or
# board number: one timeout), plus the answers a stall of this shared machine cost (20 per missed
# cycle) and the first cycles' (5)
ok $([ "${to:-99999}" -le $(( ${corrupted:-0} + 20 * ${missed:-0} + 5 )) ]; echo $?) "only the answers hit are lost ($to timeouts for $corrupted corrupted)"

# ---------------------------------------------------------------- a bus goes away and comes back
fresh_run
start_dcm
wait_for 'require("shm").open("dcm.stats").cycles[0] > 50' >/dev/null
touch "$T/bus/can1.down"
wait_for 'require("shm").open("dcm.stats").bus_down[1] == 1'; ok $? "bus 2 (can1) goes down: reported"
wait_for 'require("shm").open("dcm.stats").board_dead[12] == 1 and require("shm").open("dcm.stats").board_dead[0] == 0'
ok $? "its boards are dead, bus 1's go on"
rm -f "$T/bus/can1.down"
wait_for 'require("shm").open("dcm.stats").bus_down[1] == 0 and require("shm").open("dcm.stats").board_dead[12] == 0'
ok $? "the bus is reopened and its boards answer again"
grep -q "bus 2 (can1) reopened" "$T/dcm.log"; ok $? "the log says so"
stop_dcm
stop_emu

# ---------------------------------------------------------------- boards that come late, homing
fresh_run
start_dcm
sleep 1
start_emu
wait_for 'require("shm").open("dcm.stats").board_dead[2] == 0'; ok $? "boards powered after the DCM started are found"
repl 'Body.set_command("RKN", 0.3)' >/dev/null
for _ in $(seq 50); do s=$(emu_board JMC2); [ "${s%% *}" = 30557 ] && break; sleep 0.1; done
ok $([ "${s%% *}" = 30557 ]; echo $?) "and switched on when their status says homed: RKN 0.3 rad = 30557 counts ($s)"
stop_dcm
stop_emu
fresh_run
start_emu --unhomed
dcm_to_end --cycles 300
s=$(emu_board JMC2)
ok $([ "$(echo "$s" | awk '{print $5, $6, $7}')" = "0 0 0" ] && grep -q "board JMC2 is not homed (home state 0): left off" "$T/dcm.log"; echo $?) \
  "unhomed boards are left off and reported ($s; $(grep -m2 JMC2 "$T/dcm.log" | tr '\n' ' '))"
cp Config/platforms/Hubo/dcm.lua "$T/dcm.lua.orig"
sed -i 's/home_at_start = false/home_at_start = true/' Config/platforms/Hubo/dcm.lua
rm -f /dev/shm/hrp."$ROBOT_ID".*
dcm_to_end --cycles 300
s=$(emu_board JMC2)
ok $([ "$(echo "$s" | awk '{print $5, $6, $7}')" = "1 1 6" ] && grep -q "every board homed" "$T/dcm.log"; echo $?) \
  "home_at_start: homed, then switched on ($s)"
cp "$T/dcm.lua.orig" Config/platforms/Hubo/dcm.lua
stop_emu

# ---------------------------------------------------------------- bad tables stop start-up
cp Config/robots/hubo2plus/can.lua "$T/can.lua.orig"
sed -i "s/leg('RKN', 16, 16, 160)/leg('RKX', 16, 16, 160)/" Config/robots/hubo2plus/can.lua
err=$(timeout 10 ./run_dcm 2>&1); rc=$?
ok $([ $rc = 2 ] && echo "$err" | grep -q "Config/robots/hubo2plus/can.lua: boards\[3\] (JMC2) channels\[1\]: joint 'RKX'"; echo $?) "an unknown joint in can.lua stops start-up naming file and element ($err)"
cp "$T/can.lua.orig" Config/robots/hubo2plus/can.lua
echo "1..$n"
[ "$fails" = 0 ]
