#!/usr/bin/env python3
"""Plots a walk trace (CSV from Tools/tune/walk_trace.lua) to PNG: ZMP, COM and feet.
usage: plot_walk.py trace.csv out.png"""
import sys
import numpy as np
import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt

d = np.genfromtxt(sys.argv[1], delimiter=',', names=True)
fig, ax = plt.subplots(3, 1, figsize=(11, 11))
t = d['t']
ax[0].plot(t, d['zmp_x'], label='ZMP x')
ax[0].plot(t, d['com_x'], label='COM x')
ax[0].plot(t, d['lx'], '--', label='left foot x')
ax[0].plot(t, d['rx'], ':', label='right foot x')
ax[0].set_ylabel('x (m)'); ax[0].legend(loc='upper left'); ax[0].grid(True)
ax[1].plot(t, d['zmp_y'], label='ZMP y')
ax[1].plot(t, d['com_y'], label='COM y')
ax[1].plot(t, d['ly'], '--', label='left foot y')
ax[1].plot(t, d['ry'], ':', label='right foot y')
ax[1].set_ylabel('y (m)'); ax[1].legend(loc='upper left'); ax[1].grid(True)
ax[2].plot(d['zmp_x'], d['zmp_y'], label='ZMP')
ax[2].plot(d['com_x'], d['com_y'], label='COM')
ax[2].plot(d['lx'], d['ly'], '.', ms=2, label='left foot')
ax[2].plot(d['rx'], d['ry'], '.', ms=2, label='right foot')
ax[2].set_xlabel('x (m)'); ax[2].set_ylabel('y (m)'); ax[2].axis('equal'); ax[2].legend(); ax[2].grid(True)
ax[0].set_title(sys.argv[3] if len(sys.argv) > 3 else 'walk')
fig.tight_layout()
fig.savefig(sys.argv[2], dpi=80)
