# Shared by the scripts that run a DCM against an emulated bus (Tests/dynamixel/op_dcm_test.sh,
# Tests/hubo/hubo_dcm_test.sh, Tools/bench/dxl_wire.sh, Tools/bench/hubo_bus.sh), sourced with ROBOT_ID
# set: a scratch folder $T; the emulator's and the DCM's pids in EMU and DCM (the caller's start_emu
# and start_dcm set them: each bus starts its own way), both stopped at exit, $T removed and
# ROBOT_ID's shm segments too. The emulator takes its commands on fd 3 (`echo stats >&3`).
#   ok STATUS TEXT      the next TAP line (STATUS 0: ok); failures counted in $fails
#   repl CODE           the last line ./run_repl -e CODE prints
#   wait_for LUA_EXPR   polls the REPL until the expression prints true (10 s at most)
#   stop_emu, stop_dcm  end one (the emulator by its `quit` command)
#   emu_stats           the emulator's stats, ending in `end`, into $T/emu.out
#   dcm_to_end ARGS     start_dcm ARGS (with --cycles N) and wait for the DCM's end
#   fresh_run           before a run: ROBOT_ID's shm segments removed, $T/dcm.log emptied
T=$(mktemp -d)
EMU="" DCM=""
n=0 fails=0
ok() { n=$((n + 1)); if [ "$1" = 0 ]; then echo "ok $n - $2"; else echo "not ok $n - $2"; fails=$((fails + 1)); fi; }
dcm_emu_cleanup() {
  [ -n "$DCM" ] && kill "$DCM" 2>/dev/null
  [ -n "$EMU" ] && kill "$EMU" 2>/dev/null
  wait 2>/dev/null
  exec 3>&- 2>/dev/null
  rm -rf "$T"
  rm -f /dev/shm/hrp."$ROBOT_ID".* 2>/dev/null
}
trap dcm_emu_cleanup EXIT

repl() { ./run_repl -e "$1" 2>&1 | tail -1; }
wait_for() {
  for _ in $(seq 50); do [ "$(repl "print($1)")" = true ] && return 0; sleep 0.2; done
  return 1
}
stop_emu() { echo quit >&3; wait "$EMU" 2>/dev/null; EMU=""; exec 3>&-; }
stop_dcm() { kill "$DCM" 2>/dev/null; wait "$DCM" 2>/dev/null; DCM=""; }
emu_stats() {
  : >"$T/emu.out"; echo stats >&3
  for _ in $(seq 100); do grep -q '^end' "$T/emu.out" && break; sleep 0.02; done
}
dcm_to_end() { start_dcm "$@"; wait "$DCM"; DCM=""; }
fresh_run() { rm -f /dev/shm/hrp."$ROBOT_ID".*; : >"$T/dcm.log"; }
