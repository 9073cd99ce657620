#!/usr/bin/env bash
# Scenario (make test, real time: the watchdog matters): faults while the robot plays
# (`./run_main --sim`): kill -9 of motion, vision and behavior at random moments, each of them hung
# (SIGSTOP), motion in a busy loop, motion starved of CPU, and the DCM killed under the running Lua
# processes. Checks: the DCM's safe state when motion stops answering -- a stopped or looping motion
# within 3 DCM cycles of its last answer (the DCM's own count, dcm.stats.watchdog_lag), a starved one
# not by the stall check (only the 0.5 s timeout may trip it) --, the processes not hit keep working, run_main restarts the
# dead and the hung (the Lua processes not the DCM's restart), and the robot walks again. Prints the
# times (safe state: wall ms and DCM cycles from the fault; walking again: robot s) as figures; the
# checks count cycles, never wall time.
#   Tests/fault/faults_test.sh [FAULT ...]   env: ROBOT_ID (uses ROBOT_ID+80), FAULT_SEED (default: random)
set -u
cd "$(dirname "$0")/../.."
source Run/env.sh
LOGDIR="$HRP_ROOT/build/test-logs/fault"
mkdir -p "$LOGDIR"
ID=$(( ${ROBOT_ID:-9200} + 80 ))
SEED=${FAULT_SEED:-$((RANDOM))}
export ROBOT_ID=$ID HRP_GC_PORT=$((40000 + ID % 20000)) HRP_GC_RETURN_PORT=$((40001 + ID % 20000))
export HRP_TEAM_PORT=$((30000 + ID % 20000))
if [ ! -x build/bin/dcm_sim ]; then echo "1..1"; echo "ok 1 # SKIP needs build/bin/dcm_sim"; exit 0; fi
Tools/shm/shm --robot "$ID" remove >/dev/null 2>&1
export HRP_FAULT_BUSY="$LOGDIR/busy.$ID"   # busy:motion creates it (Player/Motion/main.lua)
rm -f "$HRP_FAULT_BUSY"
./run_main --sim --quiet >"$LOGDIR/main.log" 2>&1 &
MAIN=$!
cleanup() {
  kill -TERM "$MAIN" 2>/dev/null; wait "$MAIN" 2>/dev/null
  Tools/shm/shm --robot "$ID" remove >/dev/null 2>&1
}
trap cleanup EXIT
echo "# seed $SEED (FAULT_SEED=$SEED reproduces the order and moments)"
timeout 600 luajit Tests/fault/faults.lua "$MAIN" "$SEED" "$@" >"$LOGDIR/faults.out" 2>&1
sed 's/^/# /' "$LOGDIR/faults.out"
n=0; fails=0
check() { n=$((n + 1)); if [ "$1" = 0 ]; then echo "ok $n - $2"; else fails=$((fails + 1)); echo "not ok $n - $2"; fi; }
grep -q '^start walking' "$LOGDIR/faults.out"
check $? "the robot plays (walks) under ./run_main --sim"
field() { echo "$1" | sed -nE "s/.* $2=([^ ]+).*/\1/p"; }
while read -r line; do
  f=$(echo "$line" | awk '{print $2}')
  safe=$(field "$line" safe_ms); back=$(field "$line" walking_after); others=$(field "$line" others)
  fell=$(field "$line" fallen); p=$(field "$line" pids)
  ok=0
  [ "$back" != never ] || ok=1
  case $f in
    kill:motion) [ "$safe" != none ] || ok=1 ;;   # the DCM's safe state
    stop:motion|busy:motion)   # the DCM's safe state within 3 of its cycles after motion's last answer
      lag=$(field "$line" dcm_lag); [ "$lag" != none ] && [ "$lag" -le 3 ] || ok=1 ;;
    starve:motion)   # late but running: no trip before the timeout (its backstop) -- 50 of its 62 cycles
      tl=$(field "$line" trip_lag); [ "$tl" = none ] || [ "$tl" -ge 50 ] || ok=1 ;;
    *) [ "$safe" = none ] || ok=1 ;;   # motion kept answering: no watchdog trip
  esac
  case $f in
    kill:dcm) [ "${p%%->*}" = "${p##*->}" ] || ok=1 ;;   # the Lua processes were not restarted
    *) [ "$others" = ok ] || ok=1 ;;
  esac
  check $ok "$f: $(case $f in kill:motion|stop:motion|busy:motion) echo "safe state after $safe ms, $(field "$line" dcm_lag) DCM cycles after motion's last answer (stop and busy: at most 3), ";; starve:motion) echo "answers up to $(field "$line" max_lag) DCM cycles late, trips $(field "$line" trips) (at $(field "$line" trip_lag) cycles late; the stall check none), ";; esac)walking again after $back s of robot time (others kept working: $others; fell: $fell; pids $p)"
done < <(grep '^fault ' "$LOGDIR/faults.out")
grep -q '^end ' "$LOGDIR/faults.out"
check $? "the scenario ends with every process running"
pid=$(grep '^fault kill:motion' "$LOGDIR/faults.out" | sed -nE 's/.* pid=([0-9]+).*/\1/p')
if [ -n "$pid" ]; then
  grep -q "watchdog: the writer (pid $pid) died" "$LOGDIR/main.log"
  check $? "the DCM's log names the dead motion process (pid $pid) as the watchdog's cause"
fi
for fh in 'stop:stopped:is stopped' 'busy:looping:runs without'; do
  kind=${fh%%:*}; rest=${fh#*:}; what=${rest%%:*}; how=${rest#*:}
  pid=$(grep "^fault $kind:motion" "$LOGDIR/faults.out" | sed -nE 's/.* pid=([0-9]+).*/\1/p')
  if [ -n "$pid" ]; then
    grep -q "watchdog: the writer (pid $pid) $how" "$LOGDIR/main.log"
    check $? "the DCM's log names the $what motion process (pid $pid) as the watchdog's cause"
  fi
done
grep -E 'made no progress|ended \(|watchdog' "$LOGDIR/main.log" | sed 's/^/# main: /'
echo "1..$n"
[ $fails -eq 0 ]
