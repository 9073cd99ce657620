#!/usr/bin/env bash
# Builds the libFuzzer target of the Hubo CAN frame parser (clang) and fuzzes it for a short while.
#   make -C Modules/hubo_can fuzz-long      the 10-minute run (FUZZ_SECONDS=600 this script)
source "$(dirname "$0")/../fuzz_lib.sh"
fuzz_init 10
fuzz_build -C Modules/hubo_can fuzz
# seeds: an encoder reply, a status, an F/T, an IMU reply, a power reply, an error frame (11-byte records)
printf '\x00\x60\x08\x18\xfc\xff\xff\x40\xe2\x01\x00' >"$SEEDS/enc"
printf '\x01\x50\x08\x63\x01\x00\x00\x03\x00\x10\x00' >"$SEEDS/status"
printf '\x03\x41\x06\x10\x27\xf0\xd8\x88\x13\x00\x00\x05\x53\x08\xe8\x03\x06\xff\x94\x11\xff\xff' >"$SEEDS/ft_imu"
printf '\x06\x6e\x06\xb0\x09\x64\x00\xf8\x00\x00\x00\x20\x08\x08\x00\x00\x00\x00\x00\x00\x00\x00' >"$SEEDS/power_err"
fuzz_run can_parse "$SEEDS" build/fuzz/can_parse_fuzz -max_len=1100
fuzz_done
