#!/usr/bin/env bash
# Fuzzes (libFuzzer, clang) the colour-table loader (Modules/imageproc img_lut_load) and the
# labelling and region code on every table it accepts (Modules/imageproc/tests/img_lut_fuzz.c).
# Seeds: the table of the configured colour boxes, an empty table, a truncated and a header-only file.
#   FUZZ_SECONDS=600 Tests/vision/lut_fuzz_test.sh   for a long run.
source "$(dirname "$0")/../fuzz_lib.sh"
fuzz_init 15
fuzz_build -C Modules/imageproc fuzz
luajit -e '
  local imageproc, Config = require("imageproc"), require("Config")
  local dir = os.getenv("SEEDS")
  assert(imageproc.save_lut(dir .. "/colors.lut", imageproc.lut_from_colors(Config.load("vision").colors)))
  assert(imageproc.save_lut(dir .. "/empty.lut", imageproc.new_lut()))' || nok "seed tables"
head -c 70000 "$SEEDS/colors.lut" >"$SEEDS/truncated.lut"
head -c 16 "$SEEDS/colors.lut" >"$SEEDS/header.lut"
fuzz_run img_lut "$SEEDS" build/fuzz/img_lut_fuzz -max_len=262200
fuzz_done
