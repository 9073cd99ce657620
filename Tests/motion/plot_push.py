#!/usr/bin/env python3
"""Plots a push trace (CSV from Tests/motion/push_trace.lua) to PNG: the walk's feet and COM (its
ground frame), the capture point (planned COM + IMU capture point error), the torso's truth.
usage: plot_push.py push.csv out.png [title]"""
import sys
import numpy as np
import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt

d = np.genfromtxt(sys.argv[1], delimiter=',', names=True)
t = d['t']
# the capture point error is in the heading frame: rotate it into the walk's ground frame
a = 0.5 * (d['la'] + d['ra'])
cpx = d['com_x'] + np.cos(a) * d['cp_ex'] - np.sin(a) * d['cp_ey']
cpy = d['com_y'] + np.sin(a) * d['cp_ex'] + np.cos(a) * d['cp_ey']
fig, ax = plt.subplots(3, 1, figsize=(11, 12))
ax[0].plot(t, d['ly'], '--', label='left foot y (walk)')
ax[0].plot(t, d['ry'], ':', label='right foot y (walk)')
ax[0].plot(t, d['com_y'], label='planned COM y')
ax[0].plot(t, cpy, label='capture point y (COM + IMU error)')
ax[0].axvspan(0, 0.1, color='red', alpha=0.2, label='push')
ax[0].set_ylabel('y (m, walk frame)'); ax[0].legend(loc='upper left', fontsize=8); ax[0].grid(True)
ax[1].plot(t, d['cp_ey'], label='capture point error y')
ax[1].plot(t, d['cp_ex'], label='capture point error x')
ax[1].plot(t, d['roll'], label='torso roll (truth, rad)')
ax[1].plot(t, d['pitch'], label='torso pitch (truth, rad)')
ax[1].axvspan(0, 0.1, color='red', alpha=0.2)
ax[1].set_ylabel('m / rad'); ax[1].legend(loc='upper left', fontsize=8); ax[1].grid(True)
ax[2].plot(d['lx'], d['ly'], '.', ms=2, label='left foot')
ax[2].plot(d['rx'], d['ry'], '.', ms=2, label='right foot')
ax[2].plot(d['com_x'], d['com_y'], label='planned COM')
ax[2].plot(cpx, cpy, label='capture point')
ax[2].set_xlabel('x (m, walk frame)'); ax[2].set_ylabel('y (m)'); ax[2].axis('equal'); ax[2].legend(fontsize=8)
ax[2].grid(True)
ax[0].set_title(sys.argv[3] if len(sys.argv) > 3 else 'push')
fig.tight_layout()
fig.savefig(sys.argv[2], dpi=80)
