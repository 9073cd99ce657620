#!/usr/bin/env bash
# The recorder (TAP): a stand-in robot (fake_robot.lua) writes known values for 2 s while hrp_record
# records; check_mcap.py reads the file with the reference `mcap` library and checks every channel
# decodes and every value; the recorder exits cleanly on SIGTERM and reports its figures.
set -u
cd "$(dirname "$0")/../.."
source Run/env.sh
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
Run/shm remove >/dev/null 2>&1
build/bin/hrp_record --dir "$dir" --quiet > "$dir/record.out" 2>&1 &
rec=$!
sleep 0.5
luajit Tests/recorder/fake_robot.lua 2.0
sleep 0.3
kill -TERM $rec
wait $rec
rc=$?
echo "# $(cat "$dir/record.out")"
n=1
if [ $rc -eq 0 ] && grep -q "bytes/s" "$dir/record.out"; then echo "ok 1 - hrp_record stops on SIGTERM with its figures"
else echo "not ok 1 - hrp_record stops on SIGTERM with its figures (exit $rc)"; fi
file=$(ls "$dir"/hrp-"$ROBOT_ID"-*.mcap 2>/dev/null | head -1)
if [ -z "$file" ]; then echo "not ok 2 - a file was written"; echo "1..2"; exit 1; fi
# the checker's own TAP, renumbered after ours
missed=$(sed -n 's/.*missed ticks \([0-9]*\).*/\1/p' "$dir/record.out")
python3 Tests/recorder/check_mcap.py "$file" "$ROBOT_ID" "${missed:-0}" | while IFS= read -r line; do
  case "$line" in
    "ok "*) n=$((n + 1)); echo "ok $n - ${line#ok * - }" ;;
    "not ok "*) n=$((n + 1)); echo "not ok $n - ${line#not ok * - }" ;;
    "1.."*) echo "1..$((n))" ;;
    *) echo "# $line" ;;
  esac
done
Run/shm remove >/dev/null 2>&1
