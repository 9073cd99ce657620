#!/usr/bin/env bash
# Fuzzes the GameController packets as the robot reads them (Player/GameFSM/packet.lua, the
# controller behind the behavior): a mutational Lua fuzzer (Tests/fuzz/lua_fuzz.lua) seeded with
# valid packets built from the real layout, target Tests/game/gc_fuzz.lua (what it checks is there).
#   FUZZ_SECONDS=600 Tests/game/gc_fuzz_test.sh   for a long run.
source "$(dirname "$0")/../fuzz_lib.sh"
fuzz_init 12
fuzz_run gc_packet "$SEEDS" luajit Tests/fuzz/lua_fuzz.lua Tests.game.gc_fuzz -max_len=4096
fuzz_done
