#!/usr/bin/env python3
"""Plots a turning trace (CSV from Tools/tune/turn_trace.lua) to PNG: over the last 2 s, each hip
yaw's command and measured angle, each foot's yaw in the world (flat while it carries: a slope is a
slip) with the torso's, and the feet's loads.
usage: plot_turn.py trace.csv out.png [title]"""
import sys
import numpy as np
import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt

d = np.genfromtxt(sys.argv[1], delimiter=',', names=True)
t = d['t']
sel = t >= t[-1] - 2.0
t = t[sel]
fig, ax = plt.subplots(3, 1, figsize=(11, 10), sharex=True)
ax[0].plot(t, d['lcmd'][sel], 'b--', label='left hip yaw command')
ax[0].plot(t, d['lpos'][sel], 'b', label='left hip yaw measured')
ax[0].plot(t, d['rcmd'][sel], 'r--', label='right hip yaw command')
ax[0].plot(t, d['rpos'][sel], 'r', label='right hip yaw measured')
ax[0].set_ylabel('rad'); ax[0].legend(loc='upper left', fontsize=8); ax[0].grid(True)
un = np.unwrap
y0 = un(d['yaw'])[sel][0]
ax[1].plot(t, un(d['yaw'])[sel] - y0, 'k', label='torso yaw (truth)')
ax[1].plot(t, un(d['lyaw'])[sel] - y0, 'b', label='left foot yaw (world)')
ax[1].plot(t, un(d['ryaw'])[sel] - y0, 'r', label='right foot yaw (world)')
ax[1].plot(t, un(d['pla'])[sel] - un(d['pla'])[sel][0], 'b:', label='left foot yaw (plan, from its start)')
ax[1].plot(t, un(d['pra'])[sel] - un(d['pra'])[sel][0], 'r:', label='right foot yaw (plan, from its start)')
ax[1].set_ylabel('rad'); ax[1].legend(loc='upper left', fontsize=8); ax[1].grid(True)
ax[2].plot(t, d['fl'][sel], 'b', label='left foot force')
ax[2].plot(t, d['fr'][sel], 'r', label='right foot force')
ax[2].set_ylabel('N'); ax[2].set_xlabel('s'); ax[2].legend(loc='upper left', fontsize=8); ax[2].grid(True)
ax[0].set_title(sys.argv[3] if len(sys.argv) > 3 else 'turning')
fig.tight_layout()
fig.savefig(sys.argv[2], dpi=80)
