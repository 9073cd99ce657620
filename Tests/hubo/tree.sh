# Sourced by the Hubo scenario tests (hubo_fake_bus, start_emu, start_dcm below): hubo_tree DIR makes
# DIR a project tree for PLATFORM=Hubo ROBOT=hubo2plus -- the code and the build linked, Config copied -- with the body's robot.lua, or
# Tests/hubo/fixture_robot.lua while Config/robots/hubo2plus/robot.lua is not in the repository.
hubo_tree() {
  local dir=$1 top=${HRP_ROOT:-$PWD}
  mkdir -p "$dir"
  for x in Lib Run Player Platforms Modules Tests build run_dcm run_repl run_main; do ln -s "$top/$x" "$dir/$x"; done
  cp -r "$top/Config" "$dir/Config"
  if [ ! -f "$dir/Config/robots/hubo2plus/robot.lua" ]; then
    cp "$top/Tests/hubo/fixture_robot.lua" "$dir/Config/robots/hubo2plus/robot.lua"
  fi
}

# hubo_fake_bus (with Tests/dcm_emu_lib.sh's $T): the tree in $T/root, made the working folder, the fake
# SocketCAN's folder $T/bus for the emulator and the DCM's test build (HUBO_FAKE_CAN=1).
hubo_fake_bus() {
  hubo_tree "$T/root"
  mkdir "$T/bus"
  export FAKECAN_DIR=$T/bus HUBO_FAKE_CAN=1
  cd "$T/root" || exit 1
}
# start_emu ARGS: the Hubo emulator in the background (pid in EMU, its commands on fd 3), once ready
start_emu() {
  rm -f "$T/emu.in"; mkfifo "$T/emu.in"
  Platforms/Hubo/emulator/hubo_emulator --stdin --quiet --realtime "$@" <"$T/emu.in" >>"$T/emu.out" 2>>"$T/emu.log" &
  EMU=$!
  exec 3>"$T/emu.in"
  for _ in $(seq 100); do grep -q ready "$T/emu.log" 2>/dev/null && break; sleep 0.05; done
}
# start_dcm ARGS: ./run_dcm in the background (pid in DCM), its stderr in $T/dcm.log
start_dcm() { ./run_dcm "$@" 2>>"$T/dcm.log" & DCM=$!; }
