# Sourced by the launchers: the project's root, Lua search path, platform, body and robot id defaults.
HRP_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
export HRP_ROOT
export PATH="$HRP_ROOT/.venv/bin:$PATH"   # the project's Python (make deps)
# where ./run_dcm finds the DCMs: build/, or a sanitizer build (make sanitize sets build-address-undefined);
# the Lua processes always load build/lib (uninstrumented libraries: LuaJIT is not instrumented)
export HRP_BUILD="${HRP_BUILD:-$HRP_ROOT/build}"
export LUA_PATH="$HRP_ROOT/Lib/?.lua;$HRP_ROOT/Player/?.lua;$HRP_ROOT/?.lua;;"
export PLATFORM="${PLATFORM:-Sim}"   # what serves the blocks: Sim, OP (Config/platforms/)
export ROBOT="${ROBOT:-op3}"          # the body: op3, darwin, ... (Config/robots/)
export ROBOT_ID="${ROBOT_ID:-1}"
if [ ! -d "$HRP_ROOT/Config/platforms/$PLATFORM" ]; then
  echo "unknown platform '$PLATFORM': no folder Config/platforms/$PLATFORM (have: $(ls "$HRP_ROOT/Config/platforms" | tr '\n' ' '))" >&2
  exit 2
fi
if [ ! -d "$HRP_ROOT/Config/robots/$ROBOT" ]; then
  echo "unknown robot '$ROBOT': no folder Config/robots/$ROBOT (have: $(ls "$HRP_ROOT/Config/robots" | tr '\n' ' '))" >&2
  exit 2
fi
if [ ! -f "$HRP_ROOT/build/lib/libhrpshm.so" ]; then
  echo "not built yet: running make" >&2
  make -C "$HRP_ROOT" >&2 || exit 2
fi
