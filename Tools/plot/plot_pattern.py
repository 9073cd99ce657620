#!/usr/bin/env python3
"""Plots a walk pattern played in the sim (the log of Tests/motion/pattern_scenario.lua) to PNG:
the planned against the measured joint angles of one leg, and the planned against the measured ZMP
with the soles' extent along x and y.
usage: plot_pattern.py LOG.csv OUT_PREFIX [LEG] [TITLE] [SOLE] [SENSORS]
writes OUT_PREFIX_joints.png (LEG: l or r, default l) and OUT_PREFIX_zmp.png; SOLE: "toe,heel,inner,outer"
(m from the sole point below the ankle to each edge of the sole): each sole's extent shaded there;
SENSORS: "pressure" when the measured ZMP is the foot pressure sensors' (default: the ankle F/T); the
log's cop_x, cop_y (the sim's truth), when it has them, drawn too"""
import sys
import numpy as np
import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt

log, prefix = sys.argv[1], sys.argv[2]
leg = sys.argv[3] if len(sys.argv) > 3 else 'l'
title = sys.argv[4] if len(sys.argv) > 4 else 'pattern'
sole = [float(v) for v in sys.argv[5].split(',')] if len(sys.argv) > 5 else None
d = np.genfromtxt(log, delimiter=',', names=True)
t = d['pt']
joints = ['hip_yaw', 'hip_roll', 'hip_pitch', 'knee', 'ank_pitch', 'ank_roll']
side = {'l': 'left', 'r': 'right'}[leg]

fig, ax = plt.subplots(3, 2, figsize=(12, 9), sharex=True)
for k, j in enumerate(joints):
    a = ax[k // 2][k % 2]
    name = leg + '_' + j
    plan, meas = np.degrees(d['plan_' + name]), np.degrees(d['meas_' + name])
    rms = np.sqrt(np.mean((meas - plan) ** 2))
    a.plot(t, plan, label='planned')
    a.plot(t, meas, '--', label='measured')
    a.set_title('%s (RMS error %.2f deg)' % (name, rms), fontsize=10)
    a.set_ylabel('deg')
    a.grid(True)
    if k == 0:
        a.legend(loc='best')
for a in ax[2]:
    a.set_xlabel('time in the pattern (s)')
fig.suptitle('%s: %s leg, planned against measured joint angles' % (title, side))
fig.tight_layout()
fig.savefig(prefix + '_joints.png', dpi=80)

# the ZMP beside the soles' points (below the ankles, from the sim's truth) and, given SOLE, their
# extent (the feet are taken flat and facing along x): in single support the measured ZMP stays on the
# support sole, at its edge when the foot tips
fig, ax = plt.subplots(2, 1, figsize=(12, 8), sharex=True)
ok = d['contact'] > 0
sensors = 'foot pressure sensors' if len(sys.argv) > 6 and sys.argv[6] == 'pressure' else 'ankle F/T'

for a, axis in zip(ax, ['x', 'y']):
    a.plot(t, d['zmp_' + axis], label='planned ZMP')
    a.plot(t[ok], d['meas_' + axis][ok], '.', ms=2, label='measured ZMP (%s)' % sensors)
    if 'cop_' + axis in d.dtype.names:
        a.plot(t, d['cop_' + axis], lw=0.8, alpha=0.8, label='centre of pressure (sim truth)')
    a.plot(t, d['lsole_' + axis], ':', label='left sole point (sim)')
    a.plot(t, d['rsole_' + axis], ':', label='right sole point (sim)')
    if sole:
        toe, heel, inner, outer = sole
        for side, sgn, color in (('l', 1, 'tab:green'), ('r', -1, 'tab:red')):
            c = d[side + 'sole_' + axis]
            lo, hi = (c - heel, c + toe) if axis == 'x' else ((c - inner, c + outer) if sgn > 0 else (c - outer, c + inner))
            a.fill_between(t, lo, hi, color=color, alpha=0.12, lw=0)
    a.set_ylabel(axis + ' (m)')
    a.grid(True)
# one legend, where the x plot is empty (it starts at the origin and rises)
ax[0].legend(loc='upper left', fontsize=8)
ax[1].set_xlabel('time in the pattern (s)')
e = np.hypot(d['meas_x'][ok] - d['zmp_x'][ok], d['meas_y'][ok] - d['zmp_y'][ok])
ax[0].set_title('%s: ZMP planned against measured (RMS %.1f mm, max %.1f mm)'
                % (title, 1000 * np.sqrt(np.mean(e ** 2)), 1000 * np.max(e)))
fig.tight_layout()
fig.savefig(prefix + '_zmp.png', dpi=80)
