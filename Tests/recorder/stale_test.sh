#!/usr/bin/env bash
# tier: check (make check runs it: a few seconds)
# The recorder and a writer that died mid-update (TAP): a process leaves block 'game' with its sequence
# odd and exits; the recorder keeps sampling the other blocks at the robot's rate (the fake robot's 125 Hz
# dcm.sensor ticks: a sampler that waited on the dead block at every tick would record at most 50 of
# them a second), says once which block is stale and whose writer died, and stops on SIGTERM as usual.
set -u
cd "$(dirname "$0")/../.."
source Run/env.sh
source Tests/recorder/lib.sh

build/bin/hrp_record --dir "$dir" --camera off --quiet > "$dir/record.out" 2> "$dir/record.err" &
rec=$!
sleep 0.5
luajit -e "local w = require('shm').open('game'); w:begin_write(); w.state[0] = 3; os.exit(0)"
luajit Tests/recorder/fake_robot.lua 1.0 > /dev/null
t0=$(date +%s%N)
kill -TERM $rec
wait $rec
rc=$?
ms=$(( ($(date +%s%N) - t0) / 1000000 ))
echo "# $(cat "$dir/record.err")"
res $(( rc != 0 || ms > 3000 )) "the recorder stops on SIGTERM (${ms} ms) with a writer dead inside a block"
grep -q "block 'game' is stale: its writer (pid [0-9]*) died mid-update" "$dir/record.err"
res $? "it names the stale block and the dead writer"
[ "$(grep -c "block 'game' is stale" "$dir/record.err")" -eq 1 ]
res $? "once"
ticks=$(python3 -c "
import glob, sys
from mcap.reader import make_reader
with open(glob.glob(sys.argv[1] + '/*.mcap')[0], 'rb') as f:
    print(sum(1 for _ in make_reader(f).iter_messages(topics=['/dcm.sensor'])))" "$dir")
echo "# /dcm.sensor messages recorded after the writer died: $ticks"
[ "${ticks:-0}" -gt 80 ]
res $? "the other blocks go on being recorded at the robot's rate (${ticks:-0} of 125 ticks)"
echo "1..$n"
[ "$fails" -eq 0 ]
