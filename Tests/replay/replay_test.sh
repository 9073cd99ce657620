#!/usr/bin/env bash
# tier: check (make check runs it: a few seconds)
# The Replay platform (TAP): a recording of a stand-in robot (Tests/recorder/fake_robot.lua) served back
# by PLATFORM=Replay ./run_dcm in lockstep to a participant that checks every tick's values and every
# camera frame; faster than real time; a truncated log replayed up to the damage, which is reported; a log
# recorded with another shm schema refused with the difference named.
set -u
cd "$(dirname "$0")/../.."
source Run/env.sh
source Tests/recorder/lib.sh

# chunks written every 0.1 s (site overlay), so that the truncated log below always keeps several whole
# ones, however fast the machine produced the 2 s
mkdir -p "$dir/site"
cp Config/site/*.lua "$dir/site/" 2>/dev/null
printf 'return { flush_s = 0.1 }\n' > "$dir/site/recorder.lua"
HRP_SITE="$dir/site" rec_fake 2.0
rec_stop
read -r sensors frames < <(python3 -c "
import sys
from mcap.reader import make_reader
s = make_reader(open(sys.argv[1], 'rb')).get_summary()
ch = {c.topic: c.id for c in s.channels.values()}
n = s.statistics.channel_message_counts
print(n.get(ch['/dcm.sensor'], 0), n.get(ch['/camera.image/jpeg'], 0))" "$log")
echo "# recorded: $sensors dcm.sensor messages, $frames camera frames"
Tools/shm/shm remove >/dev/null 2>&1

# lockstep: every recorded tick reaches the participant, in order, with the recorded values
PLATFORM=Replay ./run_dcm --log "$log" --lockstep > "$dir/replay.out" 2>&1 &
dcm=$!
line=$(luajit Tests/replay/replay_checker.lua)
wait $dcm
rc=$?
echo "# $line"
sed 's/^/# /' "$dir/replay.out"
val() { echo "$line" | sed -n "s/.* $1 \([-0-9.]*\).*/\1/p"; }
[ $rc -eq 0 ] && grep -q "end of .*: $sensors ticks" "$dir/replay.out"
res $? "the Replay DCM serves every recorded tick and stops at the end of the log ($sensors ticks)"
[ "$(val ticks)" = "$sensors" ] && [ "$(val in_order)" = 1 ] && [ "$(val wrong)" = 0 ]
res $? "in lockstep the participant sees every tick, in order, with the recorded values bit for bit"
[ "$(val frames)" = "$frames" ] && [ "$(val bad_frames)" = 0 ]
res $? "every camera frame is served into camera.image (JPEG decoded back to YUYV, within 4 levels)"

# faster than real time: 2 s of log at 4x
Tools/shm/shm remove >/dev/null 2>&1
t0=$(date +%s.%N)
PLATFORM=Replay ./run_dcm --log "$log" --speed 4 --quiet
rc=$?
wall=$(echo "$(date +%s.%N) - $t0" | bc)
echo "# --speed 4: ${wall} s of wall time for 2 s of log"
# the wall time is a figure (machines are noisy); the check is that the fast replay runs to the end
[ $rc -eq 0 ]
res $? "--speed 4 replays the log to its end (${wall} s of wall time for 2 s)"

# a truncated log: read up to the damage, which is reported
size=$(stat -c %s "$log")
head -c $((size * 6 / 10)) "$log" > "$dir/cut.mcap"
Tools/shm/shm remove >/dev/null 2>&1
PLATFORM=Replay ./run_dcm --log "$dir/cut.mcap" --speed 8 > "$dir/cut.out" 2>&1
rc=$?
sed 's/^/# /' "$dir/cut.out"
ticks=$(sed -n 's/.*replayed \([0-9]*\) ticks.*/\1/p' "$dir/cut.out")
[ $rc -eq 3 ] && grep -q "damaged: .*truncated" "$dir/cut.out" && [ "${ticks:-0}" -gt $((sensors / 4)) ] &&
  [ "${ticks:-0}" -lt "$sensors" ]
res $? "a truncated log is replayed up to the damage, which is reported (exit 3)"

# a log recorded with another schema: refused, the difference named
python3 Tests/replay/alter_schema.py "$log" "$dir/other.mcap"
PLATFORM=Replay ./run_dcm --log "$dir/other.mcap" > "$dir/other.out" 2>&1
rc=$?
sed 's/^/# /' "$dir/other.out"
[ $rc -eq 2 ] && grep -q "recorded with another shm schema: block 'dcm.sensor': field 'position' is float64\[20\] in the log but float64\[32\]" "$dir/other.out"
res $? "a log recorded with another shm schema is refused naming the field"

PLATFORM=Replay ./run_dcm --log "$dir/nothere.mcap" > "$dir/none.out" 2>&1
rc=$?
[ $rc -ne 0 ] && grep -q "nothere.mcap" "$dir/none.out"
res $? "a missing log is an error naming it"
echo "1..$n"
[ "$fails" -eq 0 ]
