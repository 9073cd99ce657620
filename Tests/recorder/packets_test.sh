#!/usr/bin/env bash
# tier: check (make check runs it: a few seconds)
# The GameController packets and team messages in a recording (TAP): datagrams read through receivers
# tapped like the behavior's (packet_sender.lua) are in the MCAP file as /gamecontroller and
# /team.message, decode with their schema (hrp/msg/Packet, mcap-ros2-support) and hold the bytes that
# were sent, in order; a burst larger than the ring is recorded as far as the ring held it, and what was
# lost is counted (recorded + lost = sent).
set -u
cd "$(dirname "$0")/../.."
source Run/env.sh
source Tests/recorder/lib.sh
port=$((20000 + ROBOT_ID % 20000 * 2))   # two ports of this robot id's own

rec_start --camera off
luajit Tests/recorder/packet_sender.lua "$port" "$dir/sent.txt" 10 40
rec_stop
echo "# $(cat "$dir/record.out")"
python3 - "$dir" "$(cat "$dir/record.out")" <<'PY'
import glob, re, sys
from mcap.reader import make_reader
from mcap_ros2.decoder import DecoderFactory

d, line = sys.argv[1], sys.argv[2]
n = failed = 0
def check(cond, name, detail=""):
    global n, failed
    n += 1
    failed += 0 if cond else 1
    print(f"{'ok' if cond else 'not ok'} {n} - {name}" + (f" # {detail}" if detail else ""))

sent = [l.split() for l in open(d + "/sent.txt")]
files = glob.glob(d + "/*.mcap")
got = {"/gamecontroller": [], "/team.message": []}
with open(files[0], "rb") as f:
    r = make_reader(f, decoder_factories=[DecoderFactory()])
    for schema, channel, msg, dec in r.iter_decoded_messages(topics=list(got)):
        got[channel.topic].append((schema.name, dec))
gc, team = got["/gamecontroller"], got["/team.message"]
sent_gc = [bytes.fromhex(h) for s, h in sent if s == "gamecontroller"]
sent_team = [bytes.fromhex(h) for s, h in sent if s == "team"]
check(len(gc) == len(sent_gc) == 10 and all(s == "hrp/msg/Packet" for s, _ in gc),
      "every GameController packet is in /gamecontroller (hrp/msg/Packet)", f"{len(gc)} of {len(sent_gc)}")
check([bytes(m.data) for _, m in gc] == sent_gc, "their bytes are the packets sent, in order")
check(all(bytes(m.data)[:4] == b"RGme" and m.source == "gamecontroller" and m.host == "127.0.0.1" and m.port > 0
          for _, m in gc), "each names its source and sender (127.0.0.1) and starts with the GameController header")
check([round(m.time, 3) for _, m in gc] == [round(0.1 * i, 3) for i in range(1, 11)],
      "each carries the robot time it was read at")
slow = [bytes(m.data) for _, m in team[:10]]
check(slow == sent_team[:10], "the team messages read one by one are all there, bytes as sent")
m = re.search(r"packets (\d+), lost (\d+)", line)
taken, lost = (int(m[1]), int(m[2])) if m else (-1, -1)
rest = [bytes(m.data) for _, m in team[10:]]
# in the order sent (a subsequence of the burst: a recorder sample that falls while the burst is still
# being read, on a busy machine, takes its first part too), ending with the newest
it = iter(sent_team[10:])
in_order = all(any(r == s for s in it) for r in rest)
check(taken == len(gc) + len(team) and taken + lost == len(sent) and lost > 0 and in_order and
      bool(rest) and rest[-1] == sent_team[-1],
      "a burst beyond the ring: the newest kept in order, the rest counted as lost (recorded + lost = sent)",
      f"recorded {taken} ({len(gc) + len(team)} in the file), lost {lost}, sent {len(sent)}, in order {in_order}")
print(f"1..{n}")
sys.exit(1 if failed else 0)
PY
