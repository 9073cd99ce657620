#!/usr/bin/env bash
# Builds the libFuzzer target of the Hubo CAN frame parser (clang) and fuzzes it for a short while.
#   make -C Platforms/Hubo fuzz-long      the 10-minute run (FUZZ_SECONDS=600 this script)
set -u
cd "${HRP_ROOT:-$(dirname "$0")/../..}"
SECS=${FUZZ_SECONDS:-10}
if ! command -v clang >/dev/null; then echo "not ok 1 - clang missing (Run/install_deps.sh)"; exit 1; fi
make -s -C Platforms/Hubo fuzz >/dev/null || { echo "not ok 1 - fuzz target builds"; exit 1; }
echo "ok 1 - fuzz target builds"
FUZZ=build/fuzz/can_parse_fuzz
CORPUS=$(mktemp -d)
trap 'rm -rf "$CORPUS"' EXIT
# seeds: an encoder reply, a status, an F/T, an IMU reply, a power reply, an error frame (11-byte records)
printf '\x00\x60\x08\x18\xfc\xff\xff\x40\xe2\x01\x00' >"$CORPUS/enc"
printf '\x01\x50\x08\x63\x01\x00\x00\x03\x00\x10\x00' >"$CORPUS/status"
printf '\x03\x41\x06\x10\x27\xf0\xd8\x88\x13\x00\x00\x05\x53\x08\xe8\x03\x06\xff\x94\x11\xff\xff' >"$CORPUS/ft_imu"
printf '\x06\x6e\x06\xb0\x09\x64\x00\xf8\x00\x00\x00\x20\x08\x08\x00\x00\x00\x00\x00\x00\x00\x00' >"$CORPUS/power_err"
"$FUZZ" -max_total_time="$SECS" -max_len=1100 -rss_limit_mb=1024 -print_final_stats=1 \
  -artifact_prefix="$CORPUS/" "$CORPUS" >"$CORPUS/log" 2>&1
rc=$?
grep -E 'stat::number_of_executed_units|Done|ERROR|SUMMARY' "$CORPUS/log" | sed 's/^/# /'
if [ $rc -eq 0 ]; then echo "ok 2 - ${SECS}s of fuzzing without a crash"
else tail -40 "$CORPUS/log" | sed 's/^/# /'; echo "not ok 2 - fuzzer found a crash"; exit 1; fi
echo "1..2"
