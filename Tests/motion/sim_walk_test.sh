#!/usr/bin/env bash
# Walking scenarios of the body ROBOT (default op3) in the simulator's lockstep mode (the motion
# process alone, no behavior): standing 60 s; forward for 30 s with heading drift < 10 deg and a clean stop into
# stance; sideways and backwards; turning on the spot; 60 s of random commands; pushed over
# forwards and backwards: fall detected within 0.3 s, stands up, walks again; a kick with either
# foot sends a ball (its centre 0.1 m ahead of the toe) far and the robot stays up; the README's
# Body.set_head_command moves the head while walking, until Body.release. The speeds and
# distances each body must reach: Tests/motion/targets.lua (OP3: forward >= 0.25 m/s, sideways and
# backwards 0.1 m/s, turning 2 rad/s, kick >= 2 m). Each scenario runs in its own sim
# (Tests/motion/sim_scenarios.lua prints TAP).
#   [ROBOT=name] [SIM_SEED=N] Tests/motion/sim_walk_test.sh [SCENARIO...]   (the sim's seed, default 1)
set -u
cd "$(dirname "$0")/../.."
source Run/env.sh
source Tests/tap_lib.sh
LOGDIR="$HRP_ROOT/build/test-logs/motion"
mkdir -p "$LOGDIR"
BASE_ID=${ROBOT_ID:-9200}
SCEN=("$@")
[ ${#SCEN[@]} -eq 0 ] && SCEN=(stand forward sideways turn backward random push kick head)

if [ ! -x build/bin/dcm_sim ]; then
  echo "not ok 1 - walking scenarios: the simulator (build/bin/dcm_sim) is not built"
  exit 1
fi

n=0; failed=0; k=0
for s in "${SCEN[@]}"; do
  n=$((n + 1))
  id=$((BASE_ID + n))
  read -r -a parts <<<"$s"
  Tools/shm/shm --robot "$id" remove >/dev/null 2>&1   # stale segments of an earlier run
  ROBOT_ID=$id ./run_main --sim --quiet --no-restart --dcm-arg --lockstep-wait --dcm-arg 2 --dcm-arg --seed --dcm-arg "${SIM_SEED:-1}" \
    --dcm-arg --no-camera motion \
    >"$LOGDIR/main_${parts[0]}.log" 2>&1 &
  main_pid=$!
  # the DCM holds its clock until motion and the script have joined (--lockstep-wait 2): each run starts on the same tick
  for _ in $(seq 200); do
    grep -q 'motion started' "$LOGDIR/main_${parts[0]}.log" 2>/dev/null && break
    sleep 0.1
  done
  ROBOT_ID=$id timeout 600 ./run_repl Tests/motion/sim_scenarios.lua "${parts[@]}" >"$LOGDIR/${parts[0]}.log" 2>&1
  rc=$?
  kill -TERM "$main_pid" 2>/dev/null
  wait "$main_pid" 2>/dev/null
  Tools/shm/shm --robot "$id" remove >/dev/null 2>&1
  tap_merge "$LOGDIR/${parts[0]}.log" "${parts[0]}" "$rc"
done
[ $failed -eq 0 ]
