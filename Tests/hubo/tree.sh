# Sourced by the Hubo scenario tests: hubo_tree DIR makes DIR a project tree for PLATFORM=Hubo
# ROBOT=hubo2plus -- the code and the build linked, Config copied -- with the body's robot.lua, or
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
