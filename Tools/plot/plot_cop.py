#!/usr/bin/env python3
"""Plots the foot pressure sensors' centre of pressure against the sim's truth (the log of
Tests/motion/hoap3_pressure.lua) to PNG: x and y in the field frame over time, and the difference.
usage: plot_cop.py LOG.csv OUT.png [TITLE]"""
import sys
import numpy as np
import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt

log, out = sys.argv[1], sys.argv[2]
title = sys.argv[3] if len(sys.argv) > 3 else 'centre of pressure'
d = np.genfromtxt(log, delimiter=',', names=True, dtype=None, encoding='utf-8')
t = d['t'] - d['t'][0]
ok = np.isfinite(d['sens_x'])

fig, ax = plt.subplots(3, 1, figsize=(10, 9), sharex=True)
for a, axis in zip(ax[:2], ['x', 'y']):
    a.plot(t, d['true_' + axis], lw=2, alpha=0.6, label='truth (the ground\'s forces on the feet)')
    a.plot(t[ok], d['sens_' + axis][ok], '--', label='foot pressure sensors (4 per foot)')
    a.set_ylabel(axis + ' (m, field)')
    a.grid(True)
ax[0].legend(loc='best', fontsize=8)
e = 1000 * np.hypot(d['sens_x'][ok] - d['true_x'][ok], d['sens_y'][ok] - d['true_y'][ok])
ax[2].plot(t[ok], e, label='sensors against truth')
ax[2].plot(t[ok], 1000 * d['margin'][ok], label='sensors\' centre: margin inside the support polygon')
ax[2].set_ylabel('mm')
ax[2].set_xlabel('time (s)')
ax[2].grid(True)
ax[2].legend(loc='best', fontsize=8)
# the phases
for name in ('leaning', 'leaned', 'back'):
    sel = d['phase'] == name
    if sel.any():
        for a in ax:
            a.axvline(t[sel][0], color='grey', lw=0.5)
        ax[0].text(t[sel][0], ax[0].get_ylim()[1], ' ' + name, va='top', fontsize=8)
ax[0].set_title('%s: sensors against truth, at most %.2f mm apart' % (title, np.max(e)))
fig.tight_layout()
fig.savefig(out, dpi=80)
