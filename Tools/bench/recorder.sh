#!/usr/bin/env bash
# Benchmark: the recorder on a whole robot in the sim in real time (./run_main --sim --record: motion,
# vision, behavior, the camera at 30 Hz of sim time). Prints the bytes per second recorded and the
# recorder's CPU share as measured, then scaled to 125 Hz ticks plus 30 camera frames per second from
# the measured cost per tick and per frame (a loaded machine runs the sim slower than real time).
# Never fails on time.   Tools/bench/recorder.sh [WALL_SECONDS]   (default 20)
set -u
cd "$(dirname "$0")/../.."
source Run/env.sh
S=${1:-20}
dir=$(mktemp -d)
trap 'rm -rf "$dir"; Tools/shm/shm remove >/dev/null 2>&1' EXIT
Tools/shm/shm remove >/dev/null 2>&1
echo "machine: $(nproc) cores, load average $(cut -d' ' -f1-3 /proc/loadavg)"
./run_main --sim --record "$dir" --quiet > "$dir/main.out" 2>&1 &
main=$!
sleep "$S"
kill -INT $main
wait $main
line=$(grep '^hrp_record:' "$dir/main.out")
echo "$line"
python3 - "$dir" "$line" <<'PY'
import glob, re, sys
from mcap.reader import make_reader
d, line = sys.argv[1], sys.argv[2]
m = re.search(r"([\d.]+) s: (\d+) messages, (\d+) camera frames, (\d+) bytes .* cpu ([\d.]+) s .*JPEG ([\d.]+) ms/frame", line)
if not m:
    print("no figures from the recorder"); sys.exit(0)
wall, msgs, frames, nbytes, cpu, jpeg_ms = float(m[1]), int(m[2]), int(m[3]), int(m[4]), float(m[5]), float(m[6])
ticks = 0
for p in glob.glob(d + "/*.mcap"):
    with open(p, "rb") as f:
        s = make_reader(f).get_summary()
        ch = {c.topic: c.id for c in s.channels.values()}
        ticks += s.statistics.channel_message_counts.get(ch.get("/dcm.sensor"), 0)
jpeg = jpeg_ms / 1e3
per_tick = max(0.0, cpu - frames * jpeg) / max(ticks, 1)
print(f"seen: {ticks / wall:.1f} ticks/s, {frames / wall:.1f} frames/s, {msgs / wall:.0f} messages/s")
print(f"recorded: {nbytes / wall / 1e3:.1f} kB/s; recorder CPU {100 * cpu / wall:.2f}% of one core as measured")
print(f"cost: {1e6 * per_tick:.0f} us per tick (all blocks), {jpeg_ms:.2f} ms per 640x480 JPEG frame")
scaled = 125 * per_tick + 30 * jpeg
print(f"at 125 Hz + 30 fps: recorder CPU {100 * scaled:.1f}% of one core "
      f"(blocks {100 * 125 * per_tick:.1f}%, JPEG {100 * 30 * jpeg:.1f}%), "
      f"about {nbytes / max(ticks, 1) * 125 / 1e3:.0f} kB/s if bytes scale with ticks")
PY
