#!/usr/bin/env bash
# The sanitizer run (`make sanitize`; `make sanitize SANITIZE=thread` for ThreadSanitizer):
# builds every native part instrumented into build-<sanitizers>/ (make SANITIZE=...), runs every
# C/C++ test program of that build and the scenarios that exercise the DCMs with the instrumented
# DCM (./run_dcm takes it from HRP_BUILD); the Lua processes load the uninstrumented build/lib
# (LuaJIT itself is not instrumented). Every sanitizer report goes to a file of its own in
# build-<sanitizers>/san-logs/ (log_path): any such file is a finding and fails the run.
#   Tests/sanitize.sh                    env: SANITIZE (default address,undefined),
#                                        SAN_TESTS (regex of tests; default the C/C++ programs and
#                                        the DCM scenarios), SAN_BUILD_ONLY=1
set -u
cd "$(dirname "$0")/.."
TOP=$(pwd)
SAN="${SANITIZE:-address,undefined}"
BUILD_DIR="$TOP/build-${SAN//,/-}"
# the normal build too: the Lua processes and the tools load build/lib
make --no-print-directory SANITIZE= >"$TOP/build/sanitize-make.log" 2>&1 || {
  tail -30 "$TOP/build/sanitize-make.log"; echo "build failed (log: build/sanitize-make.log)"; exit 1; }
echo "== make SANITIZE=$SAN (into ${BUILD_DIR#"$TOP"/})"
make --no-print-directory SANITIZE="$SAN" >>"$TOP/build/sanitize-make.log" 2>&1 || {
  tail -30 "$TOP/build/sanitize-make.log"; echo "sanitizer build failed (log: build/sanitize-make.log)"; exit 1; }
[ "${SAN_BUILD_ONLY:-0}" = 1 ] && exit 0
SANLOG="$BUILD_DIR/san-logs"
rm -rf "$SANLOG"; mkdir -p "$SANLOG"
# halt on the first report, each in its own file (pid suffix); leaks too (ASan), races (TSan)
export ASAN_OPTIONS="log_path=$SANLOG/asan:halt_on_error=1:detect_leaks=1:strict_string_checks=1:detect_stack_use_after_return=1"
export UBSAN_OPTIONS="log_path=$SANLOG/ubsan:halt_on_error=1:print_stacktrace=1"
export TSAN_OPTIONS="log_path=$SANLOG/tsan:halt_on_error=1:second_deadlock_stack=1"
export HRP_BUILD="$BUILD_DIR"
if [ "$SAN" = thread ]; then
  # the threaded parts: the sim's camera worker (dcm_sim, sim_camera), camera capture (cam_v4l2_test)
  default='ctest:(sim_|cam_|shm_unit|dcm_unit)|scenario:sim/sim_dcm_test'
else
  # the fake devices are linked into the programs that use them (the camera test, the Hubo DCM's
  # test build, the CAN test), so they run here instrumented with them
  default='ctest:.|scenario:(sim/sim_dcm_test|dynamixel/op_dcm_test|fault/faults_test|hubo/hubo_dcm_test|hubo/hubo_torque_test)'
fi
TESTS="${SAN_TESTS:-$default}" Tests/run_all.sh
rc=$?
found=$(find "$SANLOG" -type f | sort)
if [ -n "$found" ]; then
  for f in $found; do echo "== sanitizer report: ${f#"$TOP"/}"; head -40 "$f"; done
  echo "sanitizer ($SAN): $(echo "$found" | wc -l) report(s)"
  exit 1
fi
echo "sanitizer ($SAN): no reports"
exit $rc
