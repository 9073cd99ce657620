# Sourced by the walk-kick scenario (walk_kick_sweep.sh) and the tuning tools (Tools/tune: kick_trace.sh,
# kick_sweep.sh, ...): moves to the project's root, sets up its environment and KICK_LOGS
# (build/test-logs/kick); kick_sim_run runs a command for one robot while its motion process runs
# alone with the sim in lockstep, then stops both.
#   kick_sim_run ID LOG COMMAND...     (SIM_SEED: the sim's seed, default 1; returns COMMAND's status)
cd "$(dirname "${BASH_SOURCE[0]}")/../.." || exit 1
source Run/env.sh
KICK_LOGS=$HRP_ROOT/build/test-logs/kick
mkdir -p "$KICK_LOGS"
kick_sim_run() {
  local id=$1 log=$2; shift 2
  Tools/shm/shm --robot "$id" remove >/dev/null 2>&1   # stale segments of an earlier run
  ROBOT_ID=$id ./run_main --sim --quiet --no-restart --dcm-arg --lockstep-wait --dcm-arg 2 --dcm-arg --seed --dcm-arg "${SIM_SEED:-1}" \
    --dcm-arg --no-camera motion >"$log" 2>&1 &
  local pid=$!
  # the DCM holds its clock until motion and the command have joined (--lockstep-wait 2): each run starts on the same tick
  for _ in $(seq 200); do
    grep -q 'motion started' "$log" 2>/dev/null && break
    sleep 0.1
  done
  sleep 0.5
  ROBOT_ID=$id "$@"
  local rc=$?
  kill -TERM "$pid" 2>/dev/null
  wait "$pid" 2>/dev/null
  Tools/shm/shm --robot "$id" remove >/dev/null 2>&1
  return $rc
}
