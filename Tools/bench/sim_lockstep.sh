#!/usr/bin/env bash
# Benchmark: real-time factor of the sim in lockstep, one standing robot, the ball, the camera
# rendering 640x480 at 30 Hz (of simulated time), with one participant that answers every tick
# like the motion process. Then where the time goes: the DCM's time per tick by phase, CPU seconds
# per simulated second (less sensitive to what else runs on the machine than the wall clock), and
# the world alone (no shm, no participant) with the camera on its worker thread, on the physics
# thread (the two must give the same frames) and without camera. Prints figures; never fails on time.
#   Tools/bench/sim_lockstep.sh [SIM_SECONDS] [--rt]      (default 30 s)
# --rt runs the DCM and the participant at real-time priority (chrt; needs the permission): on a
# machine busy with other work this stands in for a quiet one. Say so when quoting its figures.
set -u
cd "$(dirname "$0")/../.."
source Run/env.sh
S=30; DCM_PRIO=(); P_PRIO=()
for a in "$@"; do
  case "$a" in
    --rt) DCM_PRIO=(chrt -f 10); P_PRIO=(chrt -f 20) ;;   # the participant above the render thread
    *) S=$a ;;
  esac
done
if [ ${#DCM_PRIO[@]} -gt 0 ] && ! chrt -f 10 true 2>/dev/null; then
  echo "--rt: no permission for real-time priority, running at normal priority"
  DCM_PRIO=(); P_PRIO=()
fi
echo "machine: $(nproc) cores, load average $(cut -d' ' -f1-3 /proc/loadavg)${DCM_PRIO[*]:+, DCM and participant at real-time priority}"
"${DCM_PRIO[@]}" build/bin/dcm_sim --lockstep --seed 1 --quiet --profile >"${TMPDIR:-/tmp}/sim_lockstep_dcm.$$" &
dcm=$!
trap 'kill $dcm 2>/dev/null; wait $dcm 2>/dev/null; rm -f "${TMPDIR:-/tmp}/sim_lockstep_dcm.$$"; Tools/shm/shm remove >/dev/null 2>&1' EXIT
sleep 0.3
/usr/bin/time -f "participant: %U s user + %S s system" -o "${TMPDIR:-/tmp}/sim_lockstep_time.$$" \
  "${P_PRIO[@]}" luajit Tools/bench/sim_participant.lua "$S"
kill $dcm; wait $dcm 2>/dev/null
sed 's/^dcm_sim profile: /dcm_sim: /' "${TMPDIR:-/tmp}/sim_lockstep_dcm.$$"
awk -v s="$S" '{ printf "participant: CPU s per simulated s: %.4f\n", ($2 + $6) / s }' "${TMPDIR:-/tmp}/sim_lockstep_time.$$"
rm -f "${TMPDIR:-/tmp}/sim_lockstep_time.$$"
echo "world alone, camera at 30 Hz on the worker thread (as in the DCM):"
threaded=$("${DCM_PRIO[@]}" build/bin/sim_bench_world "$S")
echo "$threaded" | sed 's/^/  /'
echo "world alone, camera at 30 Hz on the physics thread:"
inline=$("${DCM_PRIO[@]}" build/bin/sim_bench_world "$S" --inline-camera)
echo "$inline" | sed 's/^/  /'
a=$(echo "$threaded" | grep 'last frame'); b=$(echo "$inline" | grep 'last frame')
if [ -n "$a" ] && [ "$a" = "$b" ]; then echo "  frames: identical on both threads ($a)"; else echo "  frames: DIFFER between the threads"; fi
echo "world alone, no camera:"
"${DCM_PRIO[@]}" build/bin/sim_bench_world "$S" --no-camera | sed 's/^/  /'
