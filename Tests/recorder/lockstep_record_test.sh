#!/usr/bin/env bash
# The recorder in lockstep (TAP): dcm_sim --lockstep runs 3 s of simulated time with the camera while
# hrp_record --lockstep is its (observer) participant: every tick is recorded, none missed, and every
# rendered frame.
set -u
cd "$(dirname "$0")/../.."
source Run/env.sh
source Tests/recorder/lib.sh
build/bin/hrp_record --lockstep --dir "$dir" --quiet > "$dir/record.out" 2>&1 &
rec=$!
build/bin/dcm_sim --lockstep-wait 1 --duration 3 --quiet
rc=$?
sleep 0.2
kill -TERM $rec
wait $rec
echo "# $(cat "$dir/record.out")"
res $rc "dcm_sim ran 3 s in lockstep with the recorder as its participant"
out=$(python3 -c "
import sys, glob
from mcap.reader import make_reader
from mcap_ros2.decoder import DecoderFactory
ticks, frames = [], 0
with open(glob.glob(sys.argv[1] + '/*.mcap')[0], 'rb') as f:
    for s, c, m, o in make_reader(f, decoder_factories=[DecoderFactory()]).iter_decoded_messages():
        if c.topic == '/dcm.sensor': ticks.append(o.tick)
        if c.topic == '/camera.image/jpeg': frames += 1
print(len(ticks), ticks[-1] - ticks[0] + 1 if ticks else 0, frames)" "$dir")
read -r got span frames <<< "$out"
echo "# $got ticks recorded over a span of $span, $frames frames"
[ "${got:-0}" -ge 370 ] && [ "$got" = "$span" ] && grep -q "missed ticks 0" "$dir/record.out"
res $? "every tick recorded, none missed (3 s at 125 Hz)"
[ "${frames:-0}" -ge 88 ] && [ "${frames:-0}" -le 92 ]
res $? "every camera frame recorded (30 per simulated second)"
echo "1..$n"
[ "$fails" -eq 0 ]
