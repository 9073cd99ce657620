#!/usr/bin/env bash
# Benchmark: real-time factor of the sim in lockstep, one standing robot, the ball, the camera
# rendering 640x480 at 30 Hz (of simulated time), with one participant that answers every tick
# like the motion process. Also the world alone (no shm, no participant) with and without camera.
# Prints figures; never fails on time.
#   Tests/bench/sim_lockstep.sh [SIM_SECONDS]      (default 30)
set -u
cd "$(dirname "$0")/../.."
source Run/env.sh
S=${1:-30}
echo "machine: $(nproc) cores, load average $(cut -d' ' -f1-3 /proc/loadavg)"
build/bin/dcm_sim --lockstep --seed 1 --quiet &
dcm=$!
trap 'kill $dcm 2>/dev/null; wait $dcm 2>/dev/null; Run/shm remove >/dev/null 2>&1' EXIT
sleep 0.3
/usr/bin/time -f "  (participant process: %U s user, %S s system)" luajit Tests/bench/sim_participant.lua "$S"
echo "  dcm.stats: $(luajit -e "local s=require('shm').open('dcm.stats'); io.write(string.format('realtime_factor %.1f over the last second, %d cycles', s.realtime_factor[0], s.cycles[0]))")"
kill $dcm; wait $dcm 2>/dev/null
echo "world alone, camera at 30 Hz:"
build/bin/sim_bench_world "$S" | sed 's/^/  /'
echo "world alone, no camera:"
build/bin/sim_bench_world "$S" --no-camera | sed 's/^/  /'
