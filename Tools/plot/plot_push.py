#!/usr/bin/env python3
"""Plots a push trace (CSV from Tools/tune/push_trace.lua) to PNG: the walk's feet and COM (its
ground frame), the capture point (planned COM + IMU capture point error), the torso's truth, and
the sideways capture point error as estimated against the truth's (the torso's position and velocity
from the sim, less the plan's, both in the heading frame at the push; tZmp from the walk config).
usage: plot_push.py push.csv out.png [title] [tZmp]"""
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
fig, ax = plt.subplots(4, 1, figsize=(11, 16))
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
# the truth's capture point against the plan's, sideways in the heading frame at the push (t = 0)
tz = float(sys.argv[4]) if len(sys.argv) > 4 else 0.165
i0 = int(np.argmin(np.abs(t)))
y0, a0 = d['yaw'][i0], a[i0]
lat = -np.sin(y0) * (d['x'] - d['x'][i0]) + np.cos(y0) * (d['y'] - d['y'][i0])
plat = -np.sin(a0) * (d['com_x'] - d['com_x'][i0]) + np.cos(a0) * (d['com_y'] - d['com_y'][i0])
cp_truth = lat + tz * np.gradient(lat, t)
cp_plan = plat + tz * np.gradient(plat, t)
ax[3].plot(t, cp_truth - cp_plan, label='capture point error y, truth (torso - plan)')
ax[3].plot(t, d['cp_ey'], label='capture point error y, estimate (IMU)')
ax[3].plot(t, tz * np.gradient(lat - plat, t), ':', label='tZmp x velocity error y, truth')
ax[3].axvspan(0, 0.1, color='red', alpha=0.2)
ax[3].set_xlim(-0.05, 1.0)
ax[3].set_xlabel('t (s)'); ax[3].set_ylabel('m'); ax[3].legend(loc='upper left', fontsize=8); ax[3].grid(True)
ax[0].set_title(sys.argv[3] if len(sys.argv) > 3 else 'push')
fig.tight_layout()
fig.savefig(sys.argv[2], dpi=80)
