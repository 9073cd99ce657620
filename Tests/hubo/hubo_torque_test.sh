#!/usr/bin/env bash
# tier: test (about 25 s of DCM and emulator on the fake SocketCAN)
# Torque mode on the Hubo DCM: dcm.actuator's torque mode becomes the motor boards' current mode on the
# bus (Platforms/Hubo/emulator/hubo_emulator and the DCM's test build on the fake SocketCAN, as
# Tests/hubo/hubo_dcm_test.sh). On JMC9 (RSY channel 0, REB channel 1; 1:1 x100 gears, 0.06 N*m/A of
# can.lua, 25 N*m drives):
#   one of its two joints in torque mode: the board stays in position mode, the joint held (refused);
#   both: H_SET_CTRL_MODE 1 reaches the board and a current reference every cycle, torque /
#   (0.06 * 100) in 0.01 A; a torque beyond the drive's 25 N*m is clamped to 4.16 A; a NaN torque:
#   H_SET_CTRL_MODE 0 and the board holds the measured position; back in torque mode, the board dies and
#   comes back (position mode first, then current mode again); then a writer
#   that stops acknowledging (a stale command): the watchdog puts the board in position mode holding
#   where it is, and the actuator block says position mode. The emulator parses every frame the DCM
#   sends.
set -u
cd "${HRP_ROOT:-$(dirname "$0")/../..}"
source Tests/hubo/tree.sh
export ROBOT_ID=$(( ${ROBOT_ID:-9400} + 90 )) PLATFORM=Hubo ROBOT=hubo2plus
source Tests/dcm_emu_lib.sh
hubo_fake_bus
# jmc9 KEY [N]: the N-th value (1: the first) after KEY in the emulator's line of board JMC9
jmc9() { emu_stats; grep "^board JMC9 " "$T/emu.out" | awk -v k="$1" -v n="${2:-1}" '{for (i = 1; i < NF; i++) if ($i == k) {print $(i + n); exit}}'; }
stat() { repl "local s = require('shm').open('dcm.stats'); print($1)"; }
# wait_jmc9 KEY VALUE [N]: up to 5 s for the value to show
wait_jmc9() { for _ in $(seq 50); do [ "$(jmc9 "$1" "${3:-1}")" = "$2" ] && return 0; sleep 0.1; done; return 1; }
blk() { repl "local a = require('shm').open('dcm.actuator'); local J = {}
  for i, name in ipairs(require('Config').load('robot').joints) do J[name] = i - 1 end
  a:write(function(x) $1 end)" >/dev/null; }

rm -f /dev/shm/hrp."$ROBOT_ID".*
start_emu
start_dcm
# references flow after the startup hold (0.8 s)
wait_for 'require("shm").open("dcm.stats").cycles[0] > 300'; ok $? "the DCM cycles against the emulated boards"

# ---------------------------------------------------------------- one joint of a two-joint board
repl 'assert(Body.set_torque("REB", -0.5))' >/dev/null
wait_for 'require("shm").open("dcm.stats").torque_refused[0] > 10'
ok $? "REB alone in torque mode: refused while RSY on the same board is in position mode (dcm.stats.torque_refused)"
m=$(jmc9 mode); mf=$(jmc9 mode_frames)
ok $([ "$m" = 0 ] && [ "$mf" = 0 ]; echo $?) "JMC9 stays in position mode: no H_SET_CTRL_MODE sent (mode $m, $mf mode frames)"
grep -q "joint REB in torque mode, but board JMC9 (RSY REB) is one control mode for all its joints" "$T/dcm.log"
ok $? "the log says why REB is held"

# ---------------------------------------------------------------- both: current mode
repl 'assert(Body.set_torque("RSY", 0.5))' >/dev/null
wait_jmc9 mode 1; ok $? "RSY and REB in torque mode: H_SET_CTRL_MODE [0x09, 0x10, 1] puts JMC9 in current mode"
# 0.5 N*m / (0.06 N*m/A * 100) = 0.0833 A -> 8 counts of 0.01 A (truncated toward zero)
wait_jmc9 amps 0.08 1 && wait_jmc9 amps -0.08 2
ok $? "current references 0.08 A (RSY, 0.5 N*m) and -0.08 A (REB, -0.5 N*m) on the bus ($(jmc9 amps 1) $(jmc9 amps 2))"
# the DCM asks every board for its encoder once a cycle: the emulator counts both in one snapshot
read -r c0 y0 e0 < <(emu_stats; grep "^board JMC9 " "$T/emu.out" | awk '{for (i = 1; i < NF; i++) {if ($i == "cur_refs") c = $(i + 1); if ($i == "enc_reqs") y = $(i + 1); if ($i == "enc") e = $(i + 2)}} END {print c, y, e}')
sleep 1
read -r c1 y1 e1 < <(emu_stats; grep "^board JMC9 " "$T/emu.out" | awk '{for (i = 1; i < NF; i++) {if ($i == "cur_refs") c = $(i + 1); if ($i == "enc_reqs") y = $(i + 1); if ($i == "enc") e = $(i + 2)}} END {print c, y, e}')
dc=$((c1 - c0)); dy=$((y1 - y0))
ok $([ "$dy" -gt 50 ] && [ "$dc" -ge $((dy - 1)) ] && [ "$dc" -le $((dy + 1)) ]; echo $?) "one current reference per cycle ($dc references, $dy encoder requests)"
# the emulated drive: 0.08 A x 6 = 0.48 N*m of 25 at stall, 0.12 rad/s of the 6.283 no-load
ok $([ $((e1 - e0)) -lt -2000 ]; echo $?) "REB turns under its current ($e0 -> $e1 counts)"

# ---------------------------------------------------------------- over the limit
repl 'assert(Body.set_torque("RSY", 1000))' >/dev/null
# clamped to the drive's 25 N*m: 25 / 6 = 4.1667 A -> 4.16
wait_jmc9 amps 4.16 1
ok $? "1000 N*m on RSY is clamped to its drive's 25 N*m: 4.16 A on the bus ($(jmc9 amps 1) A)"
cl=$(stat 's.torque_clamped[0]')
ok $([ "${cl:-0}" -gt 0 ]; echo $?) "and counted (torque_clamped $cl)"
repl 'assert(Body.set_torque("RSY", 0.5))' >/dev/null
wait_jmc9 amps 0.08 1; ok $? "back to 0.5 N*m: 0.08 A"

# ---------------------------------------------------------------- a NaN torque
mf=$(jmc9 mode_frames)
blk 'x.torque[J.REB] = 0/0'
wait_jmc9 mode 0; ok $? "a NaN torque on REB: JMC9 back in position mode (H_SET_CTRL_MODE 0)"
sleep 0.3
a=$(jmc9 enc 2); r=$(jmc9 ref 2)
sleep 0.5
b=$(jmc9 enc 2); r2=$(jmc9 ref 2)
ok $([ $((b - a)) -le 2 ] && [ $((a - b)) -le 2 ] && [ $((r2 - b)) -le 2 ] && [ $((b - r2)) -le 2 ]; echo $?) \
  "REB holds where it was: encoder $a -> $b counts in 0.5 s, reference $r2"
ok $([ "$(jmc9 mode_frames)" = $((mf + 1)) ]; echo $?) "one mode frame for the switch ($mf -> $(jmc9 mode_frames))"

# ---------------------------------------------------------------- back in torque mode
repl 'assert(Body.set_torque("REB", -0.5))' >/dev/null
wait_jmc9 mode 1; ok $? "a valid torque again: current mode again"

# ---------------------------------------------------------------- the board dies in current mode
echo "dead JMC9" >&3
wait_for 'require("shm").open("dcm.stats").board_dead[13] == 1'; ok $? "JMC9 stops answering in current mode: marked dead"
grep -q "board JMC9 (0x09, bus 2) stopped answering in current mode: joints RSY REB keep its last current" "$T/dcm.log"
ok $? "the log says its last current stays applied (it cannot be reached)"
mf=$(jmc9 mode_frames)
echo "alive JMC9" >&3
wait_for 'require("shm").open("dcm.stats").board_dead[13] == 0'; ok $? "it answers again"
wait_jmc9 mode_frames $((mf + 2)) && wait_jmc9 mode 1
order=$(grep -A2 "board JMC9 (0x09, bus 2) answers again" "$T/dcm.log" | grep -o "JMC9 (RSY REB): [a-z]* mode" | tr '\n' '|')
ok $([ "$order" = "JMC9 (RSY REB): position mode|JMC9 (RSY REB): current mode|" ]; echo $?) \
  "position mode first, then current mode again for the joints still in torque mode ($order)"
[ "$order" = "JMC9 (RSY REB): position mode|JMC9 (RSY REB): current mode|" ] || grep -A3 "JMC9" "$T/dcm.log" | tail -12 | sed 's/^/# /'

# ---------------------------------------------------------------- a stale command
# a writer acknowledging every tick, as motion does (it arms the watchdog), then stopped
./run_repl -e 'local ffi = require("ffi"); pcall(ffi.cdef, "int usleep(unsigned int);"); pcall(ffi.cdef, "int getpid(void);")
  local shm = require("shm"); local s, a = shm.open("dcm.sensor"), shm.open("dcm.actuator")
  print("writer " .. ffi.C.getpid()); io.stdout:flush()
  while true do a:write(function(x) x.tick_ack[0] = s.tick[0]; x.writer_pid[0] = ffi.C.getpid() end); ffi.C.usleep(2000) end' \
  >"$T/writer.out" 2>&1 &
WJOB=$!
for _ in $(seq 100); do grep -q '^writer' "$T/writer.out" && break; sleep 0.05; done
wpid=$(awk '/^writer/ {print $2}' "$T/writer.out")
sleep 0.5
ok $([ "$(jmc9 mode)" = 1 ] && [ "$(stat 's.watchdog_trips[0]')" = 0 ]; echo $?) "the writer acknowledges: still in current mode, no trip"
kill -STOP "$wpid"
wait_jmc9 mode 0; ok $? "the writer stops (stale commands): JMC9 back in position mode"
trips=$(stat 's.watchdog_trips[0]')
ok $([ "$trips" = 1 ] && grep -q "watchdog: the writer (pid $wpid) is stopped" "$T/dcm.log"; echo $?) "by the watchdog ($trips trip)"
sleep 0.3
a=$(jmc9 enc 2)
sleep 0.5
b=$(jmc9 enc 2); r2=$(jmc9 ref 2)
ok $([ $((b - a)) -le 2 ] && [ $((a - b)) -le 2 ] && [ $((r2 - b)) -le 2 ] && [ $((b - r2)) -le 2 ]; echo $?) \
  "REB holds where it was: encoder $a -> $b counts in 0.5 s, reference $r2"
got=$(repl 'print(Body.get_mode("RSY") .. " " .. Body.get_mode("REB"))')
ok $([ "$got" = "position position" ]; echo $?) "the actuator block says position mode: a stale torque never resumes ($got)"
kill -KILL "$wpid" 2>/dev/null; kill "$WJOB" 2>/dev/null; wait "$WJOB" 2>/dev/null
stop_dcm
grep "^board JMC9 " "$T/emu.out" | sed 's/^/# /'
emu_stats
unparsed=$(grep '^totals' "$T/emu.out" | awk '{for (i = 1; i < NF; i++) if ($i == "unparsed") print $(i + 1)}')
ok $([ "$unparsed" = 0 ]; echo $?) "the emulator parsed every frame the DCM sent ($unparsed unparsed)"
stop_emu
echo "1..$n"
[ "$fails" = 0 ]
