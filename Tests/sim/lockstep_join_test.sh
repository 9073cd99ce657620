#!/usr/bin/env bash
# tier: check (make check runs it: a few seconds)
# A script that joins the lockstep before the sim's DCM runs in lockstep (./run_repl started first,
# the DCM 1.5 s later: its world still loading, its clock not yet held) must not hold the clock for
# ever: the DCM consults every participant from its first tick on, whatever wake the script asked
# for, and the script's wait() answers it (Run/repl.lua). Prints TAP.
set -u
cd "$(dirname "$0")/../.."
source Run/env.sh
id=$(( ${ROBOT_ID:-9300} + 75 ))
LOGDIR="$HRP_ROOT/build/test-logs/sim"
mkdir -p "$LOGDIR"
Tools/shm/shm --robot "$id" remove >/dev/null 2>&1   # stale segments of an earlier run
( sleep 1.5; ROBOT_ID=$id exec ./run_main --sim --quiet --no-restart --dcm-arg --lockstep-wait --dcm-arg 2 \
    --dcm-arg --no-camera motion >"$LOGDIR/main_early_join.log" 2>&1 ) &
main_pid=$!
# 60 s of wall time for 0.3 s of robot time: only a held clock takes that long
out=$(ROBOT_ID=$id timeout 60 ./run_repl -e 'wait(0.3) print("waited", Body.get_time())' 2>&1)
rc=$?
kill -TERM "$main_pid" 2>/dev/null
wait "$main_pid" 2>/dev/null
Tools/shm/shm --robot "$id" remove >/dev/null 2>&1
echo "# $(echo "$out" | tail -1)"
if [ $rc -eq 0 ] && echo "$out" | grep -q '^waited'; then
  echo "ok 1 - a script that joined before the DCM's lockstep began: its wait() returns (the clock runs)"
else
  echo "not ok 1 - a script that joined before the DCM's lockstep began: its wait() returns (rc $rc)"
fi
echo "1..1"
[ $rc -eq 0 ]
