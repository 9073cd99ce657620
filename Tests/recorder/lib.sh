# Shared by the recorder and replay test scripts, sourced after Run/env.sh from the root: a scratch
# folder $dir, removed at exit with this robot id's shm segments (stale ones removed now too), and
# `res STATUS TEXT` printing the next TAP line and counting failures in $fails.
#   rec_start [ARGS...]   hrp_record into $dir (its output: $dir/record.out), given 0.5 s to attach
#   rec_fake SECONDS [ARGS...]   rec_start ARGS, then the stand-in robot (fake_robot.lua) writes its
#                         known values for SECONDS
#   rec_stop              0.3 s later (the last samples written) SIGTERM; the recorder's exit status;
#                         log = the recording
dir=$(mktemp -d)
rec=""
trap '[ -n "$rec" ] && kill "$rec" 2>/dev/null && wait "$rec" 2>/dev/null; rm -rf "$dir"
      Tools/shm/shm remove >/dev/null 2>&1' EXIT
rec_start() { build/bin/hrp_record --dir "$dir" --quiet "$@" >"$dir/record.out" 2>&1 & rec=$!; sleep 0.5; }
rec_fake() { local secs=$1; shift; rec_start "$@"; luajit Tests/recorder/fake_robot.lua "$secs" >/dev/null; }
rec_stop() {
  sleep 0.3
  kill -TERM "$rec"; wait "$rec"
  local rc=$?
  rec=""; log=$(ls "$dir"/hrp-*.mcap | head -1)
  return $rc
}
n=0; fails=0
res() { n=$((n + 1)); if [ "$1" = 0 ]; then echo "ok $n - $2"; else fails=$((fails + 1)); echo "not ok $n - $2"; fi; }
Tools/shm/shm remove >/dev/null 2>&1
