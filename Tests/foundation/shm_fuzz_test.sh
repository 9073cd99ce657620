#!/usr/bin/env bash
# Fuzzes (libFuzzer, clang) what the shm module reads from others: a segment's header and field
# table (opened as a schema block and as it describes itself, the tools' way), and the schema
# parser. Seeds: real segments of every block and Config/shm.schema.
#   FUZZ_SECONDS=600 Tests/foundation/shm_fuzz_test.sh   for a long run (each target).
set -u
cd "${HRP_ROOT:-$(dirname "$0")/../..}"
source Run/env.sh
SECS=${FUZZ_SECONDS:-15}
n=0; fails=0
ok() { n=$((n + 1)); echo "ok $n - $1"; }
nok() { n=$((n + 1)); fails=$((fails + 1)); echo "not ok $n - $1"; }
if ! command -v clang >/dev/null; then echo "not ok 1 - clang missing (Run/install_deps.sh)"; exit 1; fi
if make -s -C Modules/shm fuzz >/dev/null; then ok "fuzz targets build"; else nok "fuzz targets build"; echo "1..$n"; exit 1; fi
WORK=$(mktemp -d)
ID=$((ROBOT_ID + 7))
trap 'rm -rf "$WORK"; Run/shm --robot "$ID" remove >/dev/null 2>&1' EXIT
# seeds: every block of the schema as a freshly created segment, the first byte picking the block
mkdir -p "$WORK/seg" "$WORK/schema"
ROBOT_ID=$ID luajit -e '
  local shm = require("shm")
  for _, b in ipairs(shm.block_names()) do shm.open(b) end' || nok "segments for the seeds"
k=0
for b in $(luajit -e 'for _, b in ipairs(require("shm").block_names()) do print(b) end'); do
  f=/dev/shm/hrp.$ID.$b
  [ -f "$f" ] && { printf "\\x$(printf %02x $k)"; cat "$f"; } >"$WORK/seg/seed_$k"
  k=$((k + 1))
done
cp Config/shm.schema "$WORK/schema/"
for c in Config/robots/*/shm.consts; do [ -f "$c" ] && cp "$c" "$WORK/schema/$(basename "$(dirname "$c")").consts"; done
echo "# seeds: $k segments, $(ls "$WORK/schema" | wc -l) schema files"
for t in segment schema; do
  dir=$WORK/seg; [ $t = schema ] && dir=$WORK/schema
  build/fuzz/shm_${t}_fuzz -max_total_time="$SECS" -max_len=65536 -rss_limit_mb=1024 -print_final_stats=1 \
    -artifact_prefix="$WORK/" "$dir" >"$WORK/$t.log" 2>&1
  rc=$?
  grep -E 'stat::number_of_executed_units|SUMMARY|ERROR' "$WORK/$t.log" | sed "s/^/# $t: /"
  if [ $rc -eq 0 ]; then ok "shm $t parser: ${SECS} s of fuzzing without a crash"
  else tail -30 "$WORK/$t.log" | sed 's/^/# /'; nok "shm $t parser: the fuzzer found a crash"; fi
done
echo "1..$n"
[ $fails -eq 0 ]
