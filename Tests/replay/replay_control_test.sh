#!/usr/bin/env bash
# tier: check (make check runs it: a few seconds)
# Replay control from the REPL (TAP): a recording of Tests/recorder/fake_robot.lua served by the Replay
# DCM, in real time and in lockstep, paused, stepped, sought and sped up by a REPL script
# (Tests/replay/replay_control.lua); the expected times come from the log itself.
set -u
cd "$(dirname "$0")/../.."
source Run/env.sh
source Tests/recorder/lib.sh
rec_fake 2.0
rec_stop
# the log times of the ticks at or before 1.003 s and 0.5 s, of the third after the latter, of the last tick
read -r at1 at05 at05_3 last < <(python3 -c "
import sys
from mcap.reader import make_reader
r = make_reader(open(sys.argv[1], 'rb'))
ts = [m.log_time * 1e-9 for _, c, m in r.iter_messages(topics=['/dcm.sensor'])]
at = lambda t: max([x for x in ts if x <= t] or [ts[0]])
print(repr(at(1.003)), repr(at(0.5)), repr(ts[ts.index(at(0.5)) + 3]), repr(ts[-1]))" "$log")
echo "# log: ticks at or before 1.003 s: $at1, 0.5 s: $at05 (3 later: $at05_3); last $last"
n=0; fails=0
for mode in realtime lockstep; do
  Tools/shm/shm remove >/dev/null 2>&1
  flag=""; [ $mode = lockstep ] && flag=--lockstep
  PLATFORM=Replay ./run_dcm --log "$log" --paused $flag > "$dir/dcm_$mode.out" 2>&1 &
  dcm=$!
  for _ in $(seq 100); do Tools/shm/shm dump replay pid 2>/dev/null | grep -q "$dcm" && break; sleep 0.05; done
  TAP_BASE=$n TAP_PREFIX="$mode: " PLATFORM=Replay timeout 120 ./run_repl Tests/replay/replay_control.lua \
    "$at1" "$at05" "$at05_3" "$last" > "$dir/repl_$mode.out" 2>&1
  rc=$?
  if [ $mode = lockstep ]; then kill -TERM $dcm; fi
  for _ in $(seq 100); do kill -0 $dcm 2>/dev/null || break; sleep 0.05; done
  kill -0 $dcm 2>/dev/null && { echo "# $mode: the DCM did not stop"; kill -TERM $dcm; rc=1; }
  wait $dcm
  drc=$?
  grep -v '^# tests' "$dir/repl_$mode.out"
  k=$(grep -c '^\(not \)\?ok ' "$dir/repl_$mode.out")
  f=$(grep -c '^not ok ' "$dir/repl_$mode.out")
  n=$((n + k)); fails=$((fails + f))
  n=$((n + 1))
  what="resumed, the DCM serves the log to its end and stops"
  [ $mode = lockstep ] && what="the DCM stops on SIGTERM"
  if [ $rc -eq 0 ] && [ $drc -eq 0 ] && { [ $mode = lockstep ] || grep -q "end of " "$dir/dcm_$mode.out"; }; then
    echo "ok $n - $mode: $what"
  else
    fails=$((fails + 1)); echo "not ok $n - $mode: $what (repl $rc, dcm $drc)"
    sed 's/^/# /' "$dir/dcm_$mode.out" "$dir/repl_$mode.out" | tail -20
  fi
done
echo "1..$n"
[ "$fails" -eq 0 ]
