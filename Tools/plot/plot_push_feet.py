#!/usr/bin/env python3
"""Plots the feet of a push trace (CSV from Tools/tune/push_trace.lua) to PNG, in the heading at the
push (t = 0): the torso's and the soles' truth against the walk's plan (moved onto the truth at the
push), sideways and forwards (less 0.2 m/s x t, the walk's speed); the torso's and the soles' roll
and pitch (a sole on its edge, on its toe); the turn of the torso and the soles since the push (a
support foot that turns on the ground); the soles' height and the sim's foot forces (a foot in the air).
usage: plot_push_feet.py push.csv out.png [title]"""
import sys
import numpy as np
import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt

d = np.genfromtxt(sys.argv[1], delimiter=',', names=True)
t = d['t']
i0 = int(np.argmin(np.abs(t)))
y0 = d['yaw'][i0]
a0 = 0.5 * (d['la'][i0] + d['ra'][i0])


def heading(x, y, a):
    """forward and sideways in the frame turned by a"""
    return np.cos(a) * x + np.sin(a) * y, -np.sin(a) * x + np.cos(a) * y


def turn(a):
    return np.unwrap(a) - np.unwrap(a)[i0]


tf, tl = heading(d['x'], d['y'], y0)
lf, ll = heading(d['lfx'], d['lfy'], y0)
rf, rl = heading(d['rfx'], d['rfy'], y0)
pcf, pcl = heading(d['com_x'], d['com_y'], a0)
plf, pll = heading(d['lx'], d['ly'], a0)
prf, prl = heading(d['rx'], d['ry'], a0)
of, ol = tf[i0] - pcf[i0], tl[i0] - pcl[i0]
fig, ax = plt.subplots(5, 1, figsize=(11, 18), sharex=True)
ax[0].plot(t, tl, 'k', label='torso (truth)')
ax[0].plot(t, ll, 'b', label='left sole (truth)')
ax[0].plot(t, rl, 'r', label='right sole (truth)')
ax[0].plot(t, pcl + ol, 'g', label='planned COM')
ax[0].plot(t, pll + ol, 'b--', label='left foot (plan)')
ax[0].plot(t, prl + ol, 'r--', label='right foot (plan)')
ax[0].set_ylabel('sideways (m)')
v = 0.2 * t
ax[1].plot(t, tf - v, 'k', label='torso (truth)')
ax[1].plot(t, lf - v, 'b', label='left sole (truth)')
ax[1].plot(t, rf - v, 'r', label='right sole (truth)')
ax[1].plot(t, pcf + of - v, 'g', label='planned COM')
ax[1].plot(t, plf + of - v, 'b--', label='left foot (plan)')
ax[1].plot(t, prf + of - v, 'r--', label='right foot (plan)')
ax[1].set_ylabel('forward - 0.2 m/s t (m)')
ax[2].plot(t, d['roll'], 'k', label='torso roll')
ax[2].plot(t, d['pitch'], 'k:', label='torso pitch')
ax[2].plot(t, d['lfroll'], 'b', label='left sole roll')
ax[2].plot(t, d['rfroll'], 'r', label='right sole roll')
ax[2].plot(t, d['lfpitch'], 'b:', label='left sole pitch (toe down)')
ax[2].plot(t, d['rfpitch'], 'r:', label='right sole pitch (toe down)')
ax[2].set_ylabel('rad')
ax[3].plot(t, turn(d['yaw']), 'k', label='torso turn since the push')
ax[3].plot(t, turn(d['lfyaw']), 'b', label='left sole turn')
ax[3].plot(t, turn(d['rfyaw']), 'r', label='right sole turn')
ax[3].set_ylabel('rad')
ax[4].plot(t, d['lfz'], 'b', label='left sole height (m)')
ax[4].plot(t, d['rfz'], 'r', label='right sole height (m)')
ax4 = ax[4].twinx()
ax4.plot(t, d['ffl'], 'b:', label='left foot force (N)')
ax4.plot(t, d['ffr'], 'r:', label='right foot force (N)')
ax4.legend(loc='upper right', fontsize=8)
ax[4].set_ylabel('m'); ax4.set_ylabel('N'); ax[4].set_xlabel('t since the push (s)')
for a in ax:
    a.axvspan(0, 0.1, color='red', alpha=0.15)
    a.grid(True)
    a.legend(loc='upper left', fontsize=8)
ax[0].set_title(sys.argv[3] if len(sys.argv) > 3 else 'push')
fig.tight_layout()
fig.savefig(sys.argv[2], dpi=70)
