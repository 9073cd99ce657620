#!/usr/bin/env bash
# Fuzzes (libFuzzer, clang) what the shm module reads from others: a segment's header and field
# table (opened as a schema block and as it describes itself, the tools' way), and the schema
# parser. Seeds: real segments of every block and Config/shm.schema.
#   FUZZ_SECONDS=600 Tests/foundation/shm_fuzz_test.sh   for a long run (each target).
source "$(dirname "$0")/../fuzz_lib.sh"
ID=$((ROBOT_ID + 7))
FUZZ_CLEANUP="Tools/shm/shm --robot $ID remove >/dev/null 2>&1"
fuzz_init 15
fuzz_build -C Modules/shm fuzz
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
fuzz_run shm_segment "$WORK/seg" build/fuzz/shm_segment_fuzz -max_len=65536
fuzz_run shm_schema "$WORK/schema" build/fuzz/shm_schema_fuzz -max_len=65536
fuzz_done
