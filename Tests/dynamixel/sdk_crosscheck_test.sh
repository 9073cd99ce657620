#!/usr/bin/env bash
# tier: check (make check runs it: a few seconds)
# Our packets vs the ROBOTIS Python SDK 4.1.0 (byte-identical where the SDK is correct), then the
# SDK pings, reads and writes our emulator in protocol 1.0 and 2.0. TAP via the Python script.
set -u
cd "${HRP_ROOT:-$(dirname "$0")/../..}"
export HRP_ROOT=$PWD
python3 -c 'import dynamixel_sdk' 2>/dev/null || { echo "not ok 1 - dynamixel_sdk missing (Tools/deps/install_deps.sh)"; exit 1; }
python3 Tests/dynamixel/sdk_crosscheck.py || exit 1
TMP=$(mktemp -d)
EMU=""
cleanup() { [ -n "$EMU" ] && kill "$EMU" 2>/dev/null; wait 2>/dev/null; rm -rf "$TMP"; }
trap cleanup EXIT
for proto in 1 2; do
  build/bin/dxl_emulator --link "$TMP/dxl" --protocol $proto --quiet 2>"$TMP/emu.log" &
  EMU=$!
  for _ in $(seq 50); do [ -e "$TMP/dxl" ] && break; sleep 0.1; done
  python3 Tests/dynamixel/sdk_crosscheck.py --port "$TMP/dxl" --protocol $proto || exit 1
  kill "$EMU"; wait "$EMU" 2>/dev/null; EMU=""
done
