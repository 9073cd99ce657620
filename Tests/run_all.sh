#!/usr/bin/env bash
# Runs every test of the platform and ends with one line: "N passed, N failed".
#   luacheck over all Lua; busted specs (Tests/**/*_spec.lua) under LuaJIT; every C/C++ test
#   program in build/tests/; every script Tests/**/*_test.sh (integration scenarios).
# Test programs print TAP ("ok N - name" / "not ok N - name"); a program that prints no TAP
# counts as one test judged by its exit status.
#   TESTS=regex   only the tests whose name matches: luacheck, busted:Tests/<folder> (a whole folder of
#                 specs) or busted:Tests/<folder>/<file>_spec.lua (one spec file, when the regex does not
#                 match its folder's name), ctest:<program>, scenario:<folder>/<script>.sh
#   TIER=check    the fast tier (make check): luacheck, the specs, the C/C++ test programs and only the
#                 scenarios whose header has a line "# tier: check"
set -u
cd "$(dirname "$0")/.."
TOP=$(pwd)
export HRP_ROOT="$TOP"
export PATH="$TOP/.venv/bin:$PATH"   # the project's Python (make deps)
export LUA_PATH="$TOP/Lib/?.lua;$TOP/Player/?.lua;$TOP/?.lua;;"
# keep tests away from a running robot and from the fixed ids of the tools (8000-9500): each test
# takes ids up to ROBOT_ID+260, so runs sit 300 apart
export ROBOT_ID="${ROBOT_ID:-$((20000 + ($$ % 300) * 300))}"
FILTER="${TESTS:-.}"
TIER="${TIER:-all}"
case "$TIER" in all|check) ;; *) echo "run_all.sh: TIER must be 'all' or 'check', not '$TIER'" >&2; exit 2 ;; esac
LOGDIR="$TOP/build/test-logs"
mkdir -p "$LOGDIR"
TIMEOUT="${TEST_TIMEOUT:-900}"

passed=0; failed=0; skipped=0; failures=()

# run NAME CMD... : runs one test program, counts its TAP lines (or its exit status).
run() {
  local name=$1; shift
  echo "$name" | grep -Eq "$FILTER" || return 0
  local log="$LOGDIR/$(echo "$name" | tr '/ ' '__').log"
  local t0=$SECONDS
  timeout --kill-after=10 "$TIMEOUT" "$@" >"$log" 2>&1
  local rc=$?
  local ok nok skip
  skip=$(grep -ciE '^ok [0-9]+.*# *skip' "$log")
  ok=$(( $(grep -cE '^ok [0-9]+' "$log") - skip ))
  nok=$(grep -cE '^not ok [0-9]+' "$log")
  skipped=$((skipped + skip))
  if [ "$ok" -eq 0 ] && [ "$nok" -eq 0 ] && [ "$skip" -eq 0 ]; then
    if [ "$rc" -eq 0 ]; then ok=1; else nok=1; fi
  elif [ "$rc" -ne 0 ] && [ "$nok" -eq 0 ]; then
    nok=1   # crashed or timed out after its last TAP line
  fi
  passed=$((passed + ok)); failed=$((failed + nok))
  if [ "$nok" -gt 0 ]; then
    failures+=("$name")
    printf '%-50s %4d ok %3d FAILED (%ds, exit %d) -- log: %s\n' "$name" "$ok" "$nok" $((SECONDS - t0)) "$rc" "$log"
    grep -E '^not ok' "$log" | head -20 | sed 's/^/    /'
    tail -n 25 "$log" | sed 's/^/    | /'
  else
    printf '%-50s %4d ok%s (%ds)\n' "$name" "$ok" "$([ "$skip" -gt 0 ] && echo " $skip SKIPPED")" $((SECONDS - t0))
  fi
}

# 1. luacheck
mapfile -t lua_files < <(find Lib Player Run Tests Tools Config Platforms -name '*.lua' 2>/dev/null | sort)
if [ "${#lua_files[@]}" -gt 0 ]; then
  run luacheck luacheck --codes --no-color "${lua_files[@]}"
fi

# 2. busted specs, one run per folder so a crash is easy to place; a filter that names spec files
#    but not their folder runs just those files
BUSTED=(luajit /usr/bin/busted --helper=Tests/helper.lua -o TAP --pattern=_spec)
for dir in $(find Tests -name '*_spec.lua' -printf '%h\n' | sort -u); do
  if echo "busted:$dir" | grep -Eq "$FILTER"; then
    run "busted:$dir" "${BUSTED[@]}" "$dir"
  else
    for spec in $(find "$dir" -maxdepth 1 -name '*_spec.lua' | sort); do
      run "busted:$spec" "${BUSTED[@]}" "$spec"
    done
  fi
done

# 3. C/C++ test programs (HRP_BUILD: those of another build, e.g. a sanitizer build: Tests/sanitize.sh)
for prog in $(find "${HRP_BUILD:-build}/tests" -maxdepth 1 -type f -executable 2>/dev/null | sort); do
  run "ctest:$(basename "$prog")" "$prog"
done

# 4. integration scenarios (TIER=check: only those marked fast in their header)
for script in $(find Tests -name '*_test.sh' | sort); do
  if [ "$TIER" = check ] && ! grep -q '^# tier: check' "$script"; then continue; fi
  run "scenario:${script#Tests/}" bash "$script"
done

echo
if [ "${#failures[@]}" -gt 0 ]; then echo "failed: ${failures[*]}"; fi
echo "$passed passed, $failed failed, $skipped skipped"
[ "$failed" -eq 0 ]
