# Shared by the recorder and replay test scripts, sourced after Run/env.sh from the root: a scratch
# folder $dir, removed at exit with this robot id's shm segments (stale ones removed now too), and
# `res STATUS TEXT` printing the next TAP line and counting failures in $fails.
dir=$(mktemp -d)
trap 'rm -rf "$dir"; Tools/shm/shm remove >/dev/null 2>&1' EXIT
n=0; fails=0
res() { n=$((n + 1)); if [ "$1" = 0 ]; then echo "ok $n - $2"; else fails=$((fails + 1)); echo "not ok $n - $2"; fi; }
Tools/shm/shm remove >/dev/null 2>&1
