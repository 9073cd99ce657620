#!/usr/bin/env bash
# tier: check (make check runs it: a few seconds)
# The docs' "without a robot" commands for the OP platform (docs/platforms.md), run as written:
#   Platforms/OP/emulator/dxl_emulator --link /tmp/dxl
#   PLATFORM=OP ./run_dcm --port /tmp/dxl
# every servo answers for the default body (op3) and with ROBOT=darwin on both; a DCM for another
# body than the emulator's says so in one line (another protocol), not a timeout per servo.
set -u
cd "${HRP_ROOT:-$(dirname "$0")/../..}"
export HRP_ROOT=$PWD
unset ROBOT PLATFORM
export ROBOT_ID=${ROBOT_ID:-9410}
T=$(mktemp -d)
EMU="" DCM=""
n=0 fails=0
ok() { n=$((n + 1)); if [ "$1" = 0 ]; then echo "ok $n - $2"; else echo "not ok $n - $2"; fails=$((fails + 1)); fi; }
cleanup() {
  [ -n "$DCM" ] && kill "$DCM" 2>/dev/null
  [ -n "$EMU" ] && kill "$EMU" 2>/dev/null
  wait 2>/dev/null
  rm -rf "$T"
  rm -f /dev/shm/hrp."$ROBOT_ID".* 2>/dev/null
}
trap cleanup EXIT

# run EMU_ROBOT DCM_ROBOT [EMU_ARGS...]: the two commands (ROBOT set only where given); the DCM's
# log in $T/dcm.log once its start-up has counted the servos that answer
run() {
  local er=$1 dr=$2; shift 2
  rm -f /dev/shm/hrp."$ROBOT_ID".* "$T/dxl"
  if [ -n "$er" ]; then ROBOT=$er Platforms/OP/emulator/dxl_emulator --link "$T/dxl" "$@" 2>"$T/emu.log" &
  else Platforms/OP/emulator/dxl_emulator --link "$T/dxl" "$@" 2>"$T/emu.log" & fi
  EMU=$!
  for _ in $(seq 100); do [ -e "$T/dxl" ] && break; sleep 0.05; done
  if [ -n "$dr" ]; then ROBOT=$dr PLATFORM=OP ./run_dcm --port "$T/dxl" 2>"$T/dcm.log" &
  else PLATFORM=OP ./run_dcm --port "$T/dxl" 2>"$T/dcm.log" & fi
  DCM=$!
  for _ in $(seq 600); do grep -q 'servos answer' "$T/dcm.log" && break; sleep 0.05; done
  kill "$DCM" 2>/dev/null; wait "$DCM" 2>/dev/null; DCM=""
  kill "$EMU" 2>/dev/null; wait "$EMU" 2>/dev/null; EMU=""
  sed "s|$T/||; s/^/#   /" "$T/emu.log" "$T/dcm.log"
}
timeouts() { grep -c 'does not answer' "$T/dcm.log"; }

run "" ""
ok "$(grep -q 'ready .*(op3 bus 1, protocol 2, 21 devices' "$T/emu.log"; echo $?)" "default: the emulator serves the OP3's bus (protocol 2.0, 20 servos and the OpenCR)"
ok "$(grep -q '20 of 20 servos answer' "$T/dcm.log"; echo $?)" "default: the OP DCM finds every servo of the OP3"

run darwin darwin
ok "$(grep -q 'ready .*(darwin bus 1, protocol 1, 21 devices' "$T/emu.log"; echo $?)" "ROBOT=darwin: the emulator serves the DARwIn-OP's bus (protocol 1.0)"
ok "$(grep -q '20 of 20 servos answer' "$T/dcm.log"; echo $?)" "ROBOT=darwin on both: the OP DCM finds every servo"

run "" darwin --robot darwin
ok "$(grep -q 'ready .*(darwin bus 1' "$T/emu.log"; echo $?)" "--robot darwin picks the body over \$ROBOT"
ok "$(grep -q '20 of 20 servos answer' "$T/dcm.log"; echo $?)" "--robot darwin: the darwin DCM finds every servo"

# ---- the bodies differ: one line naming the protocol, no timeout per servo
run darwin ""
ok "$(grep -q 'answers in another protocol? (got protocol 1.0 bytes, expected 2.0; check ROBOT and the bus)' "$T/dcm.log"; echo $?)" \
  "emulator darwin, DCM op3: one line says the servos answer in protocol 1.0"
ok "$([ "$(timeouts)" = 0 ] && grep -q '0 of 20 servos answer' "$T/dcm.log"; echo $?)" "... and no timeout per servo ($(timeouts))"
run "" darwin
ok "$(grep -q 'answers in another protocol? (got protocol 2.0 bytes, expected 1.0' "$T/dcm.log"; echo $?)" \
  "emulator op3, DCM darwin: one line says the servos answer in protocol 2.0"
ok "$([ "$(timeouts)" = 0 ]; echo $?)" "... and no timeout per servo ($(timeouts))"
# answers that parse as no packet (a wrong baud rate looks so): one line too
run "" "" --corrupt 1
ok "$(grep -q 'answers in another protocol or baud? (got [0-9]* bytes, no protocol 2.0 packet' "$T/dcm.log" && [ "$(timeouts)" = 0 ]; echo $?)" \
  "answers that parse as no packet: one line naming them"

echo "1..$n"
[ "$fails" = 0 ]
