# Sourced by the launchers: the project's root, Lua search path, platform and robot defaults.
HRP_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
export HRP_ROOT
export LUA_PATH="$HRP_ROOT/Lib/?.lua;$HRP_ROOT/Player/?.lua;$HRP_ROOT/?.lua;;"
export PLATFORM="${PLATFORM:-Sim}"
export ROBOT_ID="${ROBOT_ID:-1}"
if [ ! -d "$HRP_ROOT/Config/$PLATFORM" ]; then
  echo "unknown platform '$PLATFORM': no folder Config/$PLATFORM (have: $(ls "$HRP_ROOT/Config" | grep -v '\.' | tr '\n' ' '))" >&2
  exit 2
fi
if [ ! -f "$HRP_ROOT/build/lib/libhrpshm.so" ]; then
  echo "not built yet: running make" >&2
  make -C "$HRP_ROOT" >&2 || exit 2
fi
