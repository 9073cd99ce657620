#!/usr/bin/env bash
# The reduced sanitizer run of make test (about a minute): the C libraries (shm, dcm, dynamixel,
# imageproc, teamcomm, the OP devices) and their test programs built with ASan+UBSan into
# build/san-quick/, the programs run with every report in a file; a report is a failure. The full
# run (every C/C++ part, the C++ sim and kinematics, the DCM scenarios): make sanitize.
set -u
cd "$(dirname "$0")/../.."
TOP=$(pwd)
B="$TOP/build/san-quick"
SANLOG="$B/san-logs"
rm -rf "$SANLOG"; mkdir -p "$SANLOG"
mk() { make --no-print-directory -C "$1" BUILD="$B" SANITIZE=address,undefined "${@:2}" >>"$B/make.log" 2>&1; }
: >"$B/make.log" 2>/dev/null || { mkdir -p "$B"; : >"$B/make.log"; }
if ! { mk Modules/shm all && mk Modules/dcm all && mk Modules/dynamixel all && mk Modules/teamcomm all &&
       mk Modules/imageproc "$B/lib/libhrpimg.so" "$B/tests/img_unit" && mk Modules/op_devices "$B/tests/op_devices_test"; }; then
  echo "not ok 1 - the C libraries build with -fsanitize=address,undefined"
  tail -20 "$B/make.log" | sed 's/^/# /'
  exit 1
fi
export ASAN_OPTIONS="log_path=$SANLOG/asan:halt_on_error=1:detect_leaks=1:detect_stack_use_after_return=1"
export UBSAN_OPTIONS="log_path=$SANLOG/ubsan:halt_on_error=1:print_stacktrace=1"
n=0; fails=0
for prog in "$B"/tests/*; do
  [ -x "$prog" ] || continue
  out=$("$prog" 2>&1); rc=$?
  ok=$(echo "$out" | grep -cE '^ok [0-9]+'); nok=$(echo "$out" | grep -cE '^not ok [0-9]+')
  n=$((n + 1))
  if [ $rc -eq 0 ] && [ "$nok" -eq 0 ]; then
    echo "ok $n - $(basename "$prog") under ASan+UBSan: $ok checks pass"
  else
    fails=$((fails + 1))
    echo "not ok $n - $(basename "$prog") under ASan+UBSan: exit $rc, $nok checks fail"
    echo "$out" | grep -E '^not ok' | head -5 | sed 's/^/# /'
  fi
done
reports=$(find "$SANLOG" -type f | sort)
n=$((n + 1))
if [ -z "$reports" ]; then echo "ok $n - no sanitizer reports"; else
  fails=$((fails + 1)); echo "not ok $n - sanitizer reports: $reports"
  for f in $reports; do head -20 "$f" | sed 's/^/# /'; done
fi
echo "1..$n"
[ $fails -eq 0 ]
