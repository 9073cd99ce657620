#!/usr/bin/env bash
# tier: check (make check runs it: a few seconds per body)
# Sim.link_truth, the simulator's world pose of any link or frame of the body (TAP), for the OP3
# and the Hubo2+ standing in lockstep (Tests/sim/link_truth.lua): the root link is Sim.truth's
# torso; the soles are on the carpet and mirror images about the torso; the hands, the camera and
# every joint's link agree with the forward kinematics from the measured joint angles; an unknown
# name is an error naming it. The figures are printed as comments.
set -u
cd "$(dirname "$0")/../.."
source Run/env.sh
ID=${ROBOT_ID:-9320}
export ROBOT_ID=$ID
LOG="$HRP_ROOT/build/test-logs/sim"
mkdir -p "$LOG"
n=0; fails=0
DCM_PID=
cleanup() {
  [ -n "$DCM_PID" ] && kill "$DCM_PID" 2>/dev/null && wait "$DCM_PID" 2>/dev/null
  DCM_PID=
  Tools/shm/shm remove >/dev/null 2>&1
}
trap cleanup EXIT
for body in op3 hubo2plus; do
  cleanup
  ROBOT=$body "$HRP_BUILD/bin/dcm_sim" --lockstep --no-camera --quiet >"$LOG/link_truth_$body.log" 2>&1 &
  DCM_PID=$!
  for _ in $(seq 100); do   # until the DCM serves the blocks
    [ -n "$(luajit -e "local s=require('shm'); local b=s.open('dcm.sensor',{try=true,attach=true}); io.write(b and b.dcm_pid[0]==$DCM_PID and 'y' or '')" 2>/dev/null)" ] && break
    sleep 0.05
  done
  out=$(ROBOT=$body timeout 120 ./run_repl Tests/sim/link_truth.lua 2>&1)
  rc=$?
  echo "$out" >"$LOG/link_truth_$body.out"
  while IFS= read -r line; do
    case "$line" in
      "pass "*) n=$((n + 1)); echo "ok $n - $body: ${line#pass }" ;;
      "fail "*) n=$((n + 1)); fails=$((fails + 1)); echo "not ok $n - $body: ${line#fail }" ;;
      *) echo "# $body: $line" ;;
    esac
  done <<<"$out"
  n=$((n + 1))
  if [ $rc -eq 0 ] && echo "$out" | grep -q '^done$'; then echo "ok $n - $body: the scenario ran to its end"
  else fails=$((fails + 1)); echo "not ok $n - $body: the scenario ran to its end (exit $rc)"; fi
done
echo "1..$n"
[ "$fails" -eq 0 ]
