#!/usr/bin/env python3
"""Compares the blocks of two recordings tick by tick (Tests/replay/game_replay_test.sh).

  compare_logs.py RECORDED REPLAYED TOPIC [TOPIC ...]

The recorder writes a block when its content changed, so a block's value at a tick is its last
message at or before that tick's dcm.sensor message. For every dcm.sensor tick of RECORDED, each
topic's value in both logs is compared as raw CDR bytes (bit for bit: NaN and -0.0 included).
Prints one line per topic and a summary:
  compare: ticks N replayed_ticks N first_t T last_t T mismatches N
  /world: values 4321 messages 834/834 mismatches 0 first_mismatch -
Exit status 0 when every tick matched and the replay had every tick, else 1.
"""
import sys

from mcap.reader import make_reader


def read(path, topics):
    """The dcm.sensor log times and each topic's (log_time, bytes) messages, in log order."""
    ticks, msgs = [], {t: [] for t in topics}
    with open(path, 'rb') as f:
        for _, channel, m in make_reader(f).iter_messages(topics=['/dcm.sensor'] + topics, log_time_order=True):
            if channel.topic == '/dcm.sensor':
                ticks.append(m.log_time)
            else:
                msgs[channel.topic].append((m.log_time, bytes(m.data)))
    return ticks, msgs


def at_ticks(ticks, msgs):
    """The value in force at each tick (None before the first message)."""
    out, k, value = [], 0, None
    for t in ticks:
        while k < len(msgs) and msgs[k][0] <= t:
            value = msgs[k][1]
            k += 1
        out.append(value)
    return out


def main():
    if len(sys.argv) < 4:
        print(__doc__)
        return 2
    rec_path, rep_path, topics = sys.argv[1], sys.argv[2], sys.argv[3:]
    rec_ticks, rec = read(rec_path, topics)
    rep_ticks, rep = read(rep_path, topics)
    # the replay serves every recorded tick, at the recorded robot time (the replay's recorder may see
    # the last one twice: the DCM publishes it again as it stops, outside the lockstep)
    same_ticks = sorted(set(rep_ticks)) == rec_ticks
    total = 0
    lines = []
    for t in topics:
        a, b = at_ticks(rec_ticks, rec[t]), at_ticks(rec_ticks, rep[t])
        bad = [i for i in range(len(rec_ticks)) if a[i] != b[i]]
        total += len(bad)
        first = '%.3f' % (rec_ticks[bad[0]] * 1e-9) if bad else '-'
        lines.append('%s: values %d messages %d/%d mismatches %d first_mismatch %s' %
                     (t, len(rec_ticks), len(rec[t]), len(rep[t]), len(bad), first))
    print('compare: ticks %d replayed_ticks %d first_t %.3f last_t %.3f mismatches %d' %
          (len(rec_ticks), len(set(rep_ticks)), rec_ticks[0] * 1e-9 if rec_ticks else -1,
           rec_ticks[-1] * 1e-9 if rec_ticks else -1, total))
    for line in lines:
        print(line)
    return 0 if same_ticks and total == 0 and rec_ticks else 1


if __name__ == '__main__':
    sys.exit(main())
