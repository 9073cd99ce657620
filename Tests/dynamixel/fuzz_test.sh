#!/usr/bin/env bash
# Builds the libFuzzer target of the Dynamixel parser (clang) and fuzzes it for a short while.
#   FUZZ_SECONDS=600 Tests/dynamixel/fuzz_test.sh   for a long run.
set -u
cd "${HRP_ROOT:-$(dirname "$0")/../..}"
SECS=${FUZZ_SECONDS:-25}
if ! command -v clang >/dev/null; then echo "not ok 1 - clang missing (Run/install_deps.sh)"; exit 1; fi
make -s -C Modules/dynamixel fuzz >/dev/null || { echo "not ok 1 - fuzz target builds"; exit 1; }
echo "ok 1 - fuzz target builds"
FUZZ=build/fuzz/dxl_parse_fuzz
CORPUS=$(mktemp -d)
trap 'rm -rf "$CORPUS"' EXIT
# seeds: valid packets of both protocols
printf '\x00\xff\xff\x01\x02\x01\xfb' >"$CORPUS/p1_ping"
printf '\x02\xff\xff\x01\x03\x00\x20\xdb' >"$CORPUS/p1_status"
printf '\x03\xff\xff\xfd\x00\x01\x08\x00\x55\x00\xa6\x00\x00\x00\x8c\xc0' >"$CORPUS/p2_status"
printf '\x01\xff\xff\xfd\x00\x01\x09\x00\x03\x74\x00\x00\x02\x00\x00\xca\x89' >"$CORPUS/p2_write"
"$FUZZ" -max_total_time="$SECS" -max_len=2048 -rss_limit_mb=1024 -print_final_stats=1 \
  -artifact_prefix="$CORPUS/" "$CORPUS" >"$CORPUS/log" 2>&1
rc=$?
grep -E 'stat::number_of_executed_units|Done|ERROR|SUMMARY' "$CORPUS/log" | sed 's/^/# /'
if [ $rc -eq 0 ]; then echo "ok 2 - ${SECS}s of fuzzing without a crash"
else tail -40 "$CORPUS/log" | sed 's/^/# /'; echo "not ok 2 - fuzzer found a crash"; exit 1; fi
