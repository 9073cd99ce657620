# Sourced by the fuzz tests (Tests/**/*fuzz_test.sh): TAP counting, a scratch folder, building the
# libFuzzer targets and one fuzz run with its figures. A run's length: FUZZ_SECONDS (each target),
# else the script's default.
#   source Tests/fuzz_lib.sh; fuzz_init 15       # cd to the repo root, WORK=scratch folder, SEEDS=$WORK/seeds
#   fuzz_build -C Modules/shm fuzz                 # make ARGS: "ok - fuzz targets build" or stop
#   fuzz_run NAME SEED_DIR CMD...                  # a libFuzzer binary or a Lua harness (same flags)
#   fuzz_done                                      # "1..N", the exit status
# FUZZ_CLEANUP: a command run at exit besides removing WORK.
set -u
cd "${HRP_ROOT:-$(dirname "${BASH_SOURCE[0]}")/..}"
source Run/env.sh
n=0; fails=0
ok() { n=$((n + 1)); echo "ok $n - $1"; }
nok() { n=$((n + 1)); fails=$((fails + 1)); echo "not ok $n - $1"; }
fuzz_done() { echo "1..$n"; [ "$fails" -eq 0 ]; exit $?; }

fuzz_init() {
  SECS=${FUZZ_SECONDS:-$1}
  WORK=$(mktemp -d)
  export SEEDS=$WORK/seeds   # (the seed makers of Lua read it)
  mkdir -p "$SEEDS"
  FUZZ_CLEANUP=${FUZZ_CLEANUP:-}
  trap 'rm -rf "$WORK"; eval "$FUZZ_CLEANUP"' EXIT
}

fuzz_build() {
  if ! command -v clang >/dev/null; then nok "clang missing (Tools/deps/install_deps.sh)"; fuzz_done; fi
  if make -s "$@" >"$WORK/build.log" 2>&1; then ok "fuzz targets build ($*)"
  else sed 's/^/# /' "$WORK/build.log" | tail -20; nok "fuzz targets build ($*)"; fuzz_done; fi
}

# fuzz_run NAME SEED_DIR CMD... : CMD gets libFuzzer's flags and the seed folder (which it grows);
# a crashing input is kept in build/fuzz-crashes/ to reproduce (CMD FILE).
fuzz_run() {
  local name=$1 seeds=$2; shift 2
  local log="$WORK/$name.log" crashes="$HRP_ROOT/build/fuzz-crashes/$name-"
  mkdir -p "$(dirname "$crashes")"
  local t0=$SECONDS
  "$@" -max_total_time="$SECS" -rss_limit_mb=1024 -print_final_stats=1 -artifact_prefix="$crashes" \
    "$seeds" >"$log" 2>&1
  local rc=$?
  local units
  units=$(sed -nE 's/^stat::number_of_executed_units: *([0-9]+).*/\1/p' "$log" | tail -1)
  grep -E 'SUMMARY|ERROR|^lua:' "$log" | head -5 | sed "s/^/# $name: /"
  echo "# $name: ${units:-?} inputs in $((SECONDS - t0)) s, corpus $(ls "$seeds" | wc -l) files, exit $rc"
  if [ $rc -eq 0 ]; then ok "$name: ${SECS} s of fuzzing without a finding"
  else tail -30 "$log" | sed 's/^/# /'; nok "$name: the fuzzer found a crash (input kept as $crashes*)"; fi
}
