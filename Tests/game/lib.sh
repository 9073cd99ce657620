# Sourced by the game scenario tests (Tests/game/*_test.sh): the project's root and environment,
# LOGDIR (build/test-logs/game), and two helpers.
cd "$(dirname "${BASH_SOURCE[0]}")/../.." || exit 1
source Run/env.sh
LOGDIR="$HRP_ROOT/build/test-logs/game"
mkdir -p "$LOGDIR"

# wait_for_clock ID: until robot ID's DCM has published a tick (at most 30 s)
wait_for_clock() {
  local tick
  for _ in $(seq 1 300); do
    tick=$(Tools/shm/shm --robot "$1" dump sync tick 2>/dev/null | awk '{print $NF}')
    [ -n "$tick" ] && [ "$tick" != 0 ] && return 0
    sleep 0.1
  done
  return 1
}

# report_checks LOG N: the play script's "check NAME ok|FAIL TEXT" lines as TAP 1..N (missing ones fail)
report_checks() {
  local log=$1 want=$2 n=0 c
  local checks
  mapfile -t checks < <(grep '^check ' "$log")
  echo "1..$want"
  for c in "${checks[@]}"; do
    n=$((n + 1))
    set -- $c
    if [ "$3" = ok ]; then echo "ok $n - $2: ${c#check $2 ok }"; else echo "not ok $n - $2: ${c#check $2 FAIL }"; fi
  done
  for i in $(seq $((n + 1)) "$want"); do echo "not ok $i - missing check (see $log)"; done
  tail -3 "$log" | sed 's/^/# /'
}
