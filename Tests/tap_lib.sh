# Shared by the scenario scripts that run several scenario programs and print one TAP sequence.
# tap_merge LOG LABEL RC: copies LOG's TAP lines into this script's sequence (the caller's k and
# failed counters), each test named after LABEL; a program that exited with RC != 0 is one more
# failure, shown with the log's tail.
tap_merge() {
  local log=$1 label=$2 rc=$3 line
  while IFS= read -r line; do
    if [[ $line =~ ^(not\ ok|ok)\ [0-9]+\ -\ (.*)$ ]]; then
      k=$((k + 1)); echo "${BASH_REMATCH[1]} $k - $label: ${BASH_REMATCH[2]}"
      [[ ${BASH_REMATCH[1]} == "not ok" ]] && failed=$((failed + 1))
    elif [[ $line == \#* ]]; then echo "$line"; fi
  done <"$log"
  if [ "$rc" -ne 0 ]; then
    k=$((k + 1)); failed=$((failed + 1))
    echo "not ok $k - $label: scenario script exited with status $rc (log $log)"
    tail -n 5 "$log" | sed 's/^/#   /'
  fi
  return 0
}

# lockstep_scenario ID LABEL SCRIPT [ARGS...]: the sim's robot ROBOT_ID=ID in lockstep (the DCM holds
# its first tick for two participants: motion and the script; no camera) with ./run_main motion, and
# ./run_repl SCRIPT ARGS as the second (at most 300 s); then both stopped, the robot's blocks removed
# and the script's TAP merged under LABEL (tap_merge). ROBOT, HRP_SITE and the like come from the
# caller's environment; SCENARIO_DCM_ARGS adds arguments for the DCM (e.g. "--seed 3"),
# SCENARIO_TIMEOUT another bound for the script (s). The logs: $LOGDIR/main_LABEL.log and $LOGDIR/LABEL.log.
lockstep_scenario() {
  local id=$1 label=$2 script=$3 arg main_pid rc
  shift 3
  local dcm_args=(--dcm-arg --lockstep-wait --dcm-arg 2 --dcm-arg --no-camera)
  for arg in ${SCENARIO_DCM_ARGS:-}; do dcm_args+=(--dcm-arg "$arg"); done
  Tools/shm/shm --robot "$id" remove >/dev/null 2>&1   # stale segments of an earlier run
  ROBOT_ID=$id ./run_main --sim --quiet --no-restart "${dcm_args[@]}" motion >"$LOGDIR/main_$label.log" 2>&1 &
  main_pid=$!
  for _ in $(seq 200); do grep -q 'motion started' "$LOGDIR/main_$label.log" 2>/dev/null && break; sleep 0.1; done
  ROBOT_ID=$id timeout "${SCENARIO_TIMEOUT:-300}" ./run_repl "$script" "$@" >"$LOGDIR/$label.log" 2>&1
  rc=$?
  kill -TERM "$main_pid" 2>/dev/null
  wait "$main_pid" 2>/dev/null
  Tools/shm/shm --robot "$id" remove >/dev/null 2>&1
  tap_merge "$LOGDIR/$label.log" "$label" "$rc"
}

# scenario_logs AREA: the scenario's log folder build/test-logs/AREA in LOGDIR (made), its TAP counters
# (k, failed) at zero.
scenario_logs() {
  LOGDIR="$HRP_ROOT/build/test-logs/$1"
  mkdir -p "$LOGDIR"
  failed=0; k=0
}

# solver_site ITERATIONS: a site overlay (build/solver-site-N: the site's files and a sim.lua) with
# that many dWorldQuickStep iterations, exported as HRP_SITE: a solver setting, not physics, for
# comparing a scenario's figures with the body's own.
solver_site() {
  local site="$HRP_ROOT/build/solver-site-$1"
  rm -rf "$site"; mkdir -p "$site"
  cp Config/site/*.lua "$site/"
  printf 'return { physics = { iterations = %d } }\n' "$1" >"$site/sim.lua"
  export HRP_SITE=$site
}
