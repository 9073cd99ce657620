#!/usr/bin/env python3
"""Plots a walk-kick trace (WALK_KICK_TRACE from Tests/motion/walk_kick_scenario.lua) to PNG: for each
case the kicking foot's toe (FK of the measured joints on the sim's torso truth) and the ball in the
field from above, relative to the ball's start, plus the toe's height and forward/sideways position
and the ball's over time.
usage: plot_walk_kick.py trace.txt out.png [CASES, e.g. 1,5]"""
import sys
import numpy as np
import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt

rows = [l.split() for l in open(sys.argv[1]) if not l.startswith('#')]
d = np.array([[float(v) for v in r[:10]] for r in rows])
cases = sorted(set(d[:, 0].astype(int)))
if len(sys.argv) > 3:
    cases = [int(c) for c in sys.argv[3].split(',')]
fig, ax = plt.subplots(len(cases), 2, figsize=(14, 4.2 * len(cases)), squeeze=False)
for k, c in enumerate(cases):
    e = d[d[:, 0] == c]
    t, tx, ty, tz, bx, by, bz = e[:, 1], e[:, 2], e[:, 3], e[:, 4], e[:, 5], e[:, 6], e[:, 7]
    ox, oy = bx[0], by[0]
    a = ax[k, 0]
    a.plot(tx - ox, ty - oy, '.-', ms=2, label='toe (top view)')
    a.plot(bx - ox, by - oy, '.-', ms=2, label='ball centre')
    a.plot(e[:, 8] - ox, e[:, 9] - oy, '-', lw=0.8, label='torso')
    a.add_patch(plt.Circle((0, 0), 0.07, fill=False, color='C1'))
    a.set_aspect('equal'); a.grid(True); a.legend(fontsize=8); a.set_title('case %d: field, m from the ball' % c)
    a.set_xlim(-0.5, 1.0); a.set_ylim(-0.5, 0.5)
    b = ax[k, 1]
    b.plot(t, tz, label='toe height')
    b.plot(t, tx - ox, label='toe x - ball x0')
    b.plot(t, ty - oy, label='toe y - ball y0')
    b.plot(t, bx - ox, label='ball x - x0')
    b.plot(t, by - oy, label='ball y - y0')
    b.set_xlabel('s after the request'); b.set_ylabel('m'); b.grid(True); b.legend(fontsize=8)
fig.tight_layout()
fig.savefig(sys.argv[2], dpi=80)
