#!/usr/bin/env bash
# tier: check (make check runs it: a few seconds)
# The recorder (TAP): a stand-in robot (fake_robot.lua) writes known values for 2 s while hrp_record
# records; check_mcap.py reads the file with the reference `mcap` library and checks every channel
# decodes and every value; the recorder exits cleanly on SIGTERM and reports its figures; then
# rotation and the size cap with tiny files.
set -u
cd "$(dirname "$0")/../.."
source Run/env.sh
source Tests/recorder/lib.sh

rec_start
luajit Tests/recorder/fake_robot.lua 2.0
rec_stop
rc=$?
echo "# $(cat "$dir/record.out")"
grep -q "bytes/s" "$dir/record.out"
res $(( rc != 0 || $? != 0 )) "hrp_record stops on SIGTERM with its figures"
file=$(ls "$dir"/hrp-"$ROBOT_ID"-*.mcap 2>/dev/null | head -1)
missed=$(sed -n 's/.*missed ticks \([0-9]*\).*/\1/p' "$dir/record.out")
if [ -n "$file" ]; then
  # the checker's own TAP, renumbered after ours
  while IFS= read -r line; do
    case "$line" in
      "ok "*) res 0 "${line#ok * - }" ;;
      "not ok "*) res 1 "${line#not ok * - }" ;;
      "1.."*) ;;
      *) echo "# $line" ;;
    esac
  done < <(python3 Tests/recorder/check_mcap.py "$file" "$ROBOT_ID" "${missed:-0}" 2>&1)
else
  res 1 "a file was written"
fi

# rotation and the size cap: files of 60 kB (the attached config alone is ~25 kB), at most 150 kB kept; every file left is whole
rot="$dir/rot"
build/bin/hrp_record --dir "$rot" --quiet --file-mb 0.06 --total-mb 0.15 > "$dir/rot.out" 2>&1 &
rec=$!
sleep 0.3
luajit Tests/recorder/fake_robot.lua 1.5 >/dev/null
kill -TERM $rec
wait $rec
files=$(ls "$rot" | grep -c '\.mcap$')
begun=$(sed -n 's/.* in \([0-9]*\) file(s).*/\1/p' "$dir/rot.out")
total=$(du -cb "$rot"/*.mcap | tail -1 | cut -f1)
read -r whole split < <(python3 -c "
import sys, glob
from mcap.reader import make_reader
ok = msgs = 0
seen = []   # the ticks (log times) of each file: a tick split across two files would be in both
for p in glob.glob(sys.argv[1] + '/*.mcap'):
    with open(p, 'rb') as f:
        r = make_reader(f)
        ok += r.get_summary() is not None
        times = set(m.log_time for _, _, m in r.iter_messages())
        msgs += len(times)
        seen.append(times)
split = sum(len(a & b) for i, a in enumerate(seen) for b in seen[i + 1:])
print(ok if msgs else -1, split)" "$rot")
echo "# rotation: ${begun:-0} files begun, $files kept, $total bytes, $whole whole, $split ticks in two files"
[ "${begun:-0}" -ge 3 ] && [ "$files" -lt "${begun:-0}" ] && [ "$total" -le 210000 ] && [ "$whole" -eq "$files" ]
res $? "rotation: a new file past file_mb, the oldest deleted past total_mb, every file kept is whole"
[ "$split" = 0 ]
res $? "rotation never splits a tick: no robot time is in two files"
echo "1..$n"
[ "$fails" -eq 0 ]
