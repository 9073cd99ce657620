#!/usr/bin/env bash
# Fuzzes teammates' messages as the robot reads them: the decoder (Modules/teamcomm tc_decode,
# libFuzzer, clang; Modules/teamcomm/tests/tc_decode_fuzz.c) and the team table behind it
# (Player/Team/team.lua through the FFI; Lua fuzzer Tests/fuzz/lua_fuzz.lua, target
# Tests/team/team_fuzz.lua). Seeds: messages encoded by Team.message.
#   FUZZ_SECONDS=600 Tests/team/teamcomm_fuzz_test.sh   for a long run (each target).
source "$(dirname "$0")/../fuzz_lib.sh"
fuzz_init 12
fuzz_build -C Modules/teamcomm fuzz
mkdir -p "$WORK/lua" "$WORK/c"
fuzz_run team_table "$WORK/lua" luajit Tests/fuzz/lua_fuzz.lua Tests.team.team_fuzz -max_len=2100
cp "$WORK"/lua/* "$WORK/c/"   # the Lua run's seeds and finds seed the decoder's run
fuzz_run tc_decode "$WORK/c" build/fuzz/tc_decode_fuzz -max_len=2100
fuzz_done
