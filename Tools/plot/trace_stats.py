#!/usr/bin/env python3
"""Where the time goes in scoring runs: per seed and on average, the time in each body state (and how
often it was entered), the falls (and the state they happened in), the robot's speed while
dribbling, the outcome, and per body state the forward speed commanded, the walk's (rate-limited) and
the truth's along the heading (traces with the command columns).

    Tools/plot/trace_stats.py DIR [DIR ...]     (DIR: a score_test.sh log folder, e.g.
                                                      build/test-logs/scenarios)

Reads DIR/trace_SEED.txt (Tests/scenarios/score_one.lua's trace: "t x y yaw bx by fallen px py pyaw
wbx wby ball_age body motion confidence head [cmd_vx cmd_vy cmd_va walk_vx walk_vy walk_va]") and
DIR/run_SEED.log (its result line).
"""
import collections
import glob
import math
import os
import re
import statistics
import sys


def read_trace(path):
    rows = []
    with open(path) as f:
        for line in f:
            if line.startswith('#') or line.startswith('post'):
                continue
            p = line.split()
            if len(p) < 14:
                continue
            cmd = (float(p[17]), float(p[20])) if len(p) >= 23 else None
            rows.append((float(p[0]), float(p[1]), float(p[2]), int(p[6]), p[13], float(p[3]), cmd))
    return rows


def outcome(folder, seed):
    path = os.path.join(folder, 'run_%s.log' % seed)
    if not os.path.exists(path):
        return None
    with open(path) as f:
        lines = [l for l in f if l.startswith('result')]
    if not lines:
        return None
    m = re.search(r'goal=(\d) time=([0-9.]+)', lines[-1])
    return float(m.group(2)) if m and m.group(1) == '1' else None


def summarise(folder):
    paths = glob.glob(os.path.join(folder, 'trace_*.txt'))
    seeds = sorted((os.path.basename(p)[6:-4] for p in paths), key=lambda s: (len(s), s))
    total = collections.defaultdict(float)
    times, n, falls_all, drib_t, drib_m = [], 0, 0, 0.0, 0.0
    # per state, while upright: time, and the integrals of commanded, walk and true forward speed
    speed = collections.defaultdict(lambda: [0.0, 0.0, 0.0, 0.0])
    print('%s' % folder)
    for seed in seeds:
        rows = read_trace(os.path.join(folder, 'trace_%s.txt' % seed))
        if len(rows) < 2:
            continue
        n += 1
        spent, entered, falls = collections.defaultdict(float), collections.Counter(), []
        prev_state, prev_fallen = None, 0
        for a, b in zip(rows, rows[1:] + [None]):
            if a[3] and not prev_fallen:
                falls.append('%s@%.0f' % (prev_state, a[0]))
            if b is not None:
                dt = b[0] - a[0]
                spent[a[4]] += dt
                if a[4] != prev_state:
                    entered[a[4]] += 1
                if a[6] is not None and not a[3] and b[4] == a[4] and dt > 0:
                    fwd = math.cos(a[5]) * (b[1] - a[1]) + math.sin(a[5]) * (b[2] - a[2])
                    sp = speed[a[4]]
                    sp[0] += dt
                    sp[1] += a[6][0] * dt
                    sp[2] += a[6][1] * dt
                    sp[3] += fwd
                if a[4] == 'dribble':
                    drib_t += dt
                    drib_m += math.hypot(b[1] - a[1], b[2] - a[2])
            prev_state, prev_fallen = a[4], a[3]
        for k, v in spent.items():
            total[k] += v
        falls_all += len(falls)
        t = outcome(folder, seed)
        times.append(t)
        states = ' '.join('%s %.1f(%d)' % (k, v, entered[k]) for k, v in sorted(spent.items(), key=lambda x: -x[1]))
        print('  seed %s: %s  falls %d%s  %s' % (seed, 'goal %.1f s' % t if t is not None else 'no goal',
                                              len(falls), ' (' + ', '.join(falls) + ')' if falls else '', states))
    if n == 0:
        print('  no traces')
        return
    goals = [t for t in times if t is not None]
    # a run without a goal counts as slower than any with one
    med = statistics.median([t if t is not None else math.inf for t in times])
    print('  %d/%d goals, median %s s, falls %d, dribbling at %.3f m/s' % (
        len(goals), n, '%.1f' % med if med != math.inf else 'none', falls_all, drib_m / drib_t if drib_t else 0))
    print('  mean s per run: ' + ' '.join('%s %.1f' % (k, v / n) for k, v in sorted(total.items(), key=lambda x: -x[1])))
    if speed:
        print('  forward m/s (commanded, walk, true): ' + ', '.join(
            '%s %.3f %.3f %.3f' % (k, v[1] / v[0], v[2] / v[0], v[3] / v[0])
            for k, v in sorted(speed.items(), key=lambda x: -x[1][0]) if v[0] > 0))


if __name__ == '__main__':
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    for d in sys.argv[1:]:
        summarise(d)
