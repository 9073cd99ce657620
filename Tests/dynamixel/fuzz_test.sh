#!/usr/bin/env bash
# Builds the libFuzzer target of the Dynamixel parser (clang) and fuzzes it for a short while.
#   FUZZ_SECONDS=600 Tests/dynamixel/fuzz_test.sh   for a long run.
source "$(dirname "$0")/../fuzz_lib.sh"
fuzz_init 25
fuzz_build -C Modules/dynamixel fuzz
# seeds: valid packets of both protocols
printf '\x00\xff\xff\x01\x02\x01\xfb' >"$SEEDS/p1_ping"
printf '\x02\xff\xff\x01\x03\x00\x20\xdb' >"$SEEDS/p1_status"
printf '\x03\xff\xff\xfd\x00\x01\x08\x00\x55\x00\xa6\x00\x00\x00\x8c\xc0' >"$SEEDS/p2_status"
printf '\x01\xff\xff\xfd\x00\x01\x09\x00\x03\x74\x00\x00\x02\x00\x00\xca\x89' >"$SEEDS/p2_write"
fuzz_run dxl_parse "$SEEDS" build/fuzz/dxl_parse_fuzz -max_len=2048
fuzz_done
