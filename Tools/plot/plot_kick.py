#!/usr/bin/env python3
"""Plots a kick trace (CSV from Tools/tune/kick_trace.lua) to PNG: the toe's forward speed (world,
and relative to the torso from the joint velocities), the ball's speed, the kicking leg's joint
velocities against the servo limit, the toe's height, the balance (COM and capture point against the
support foot's ankle, the torso's yaw) and the ball's distance.
usage: plot_kick.py trace.csv out.png [title]"""
import sys
import numpy as np
import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt

d = np.genfromtxt(sys.argv[1], delimiter=',', names=True)
t = d['t']
bs = np.hypot(d['bvx'], d['bvy'])
moving = np.nonzero(bs > 0.05)[0]
t0, t1 = (t[moving[0]] - 0.25, t[moving[0]] + 0.25) if len(moving) else (t[0], t[-1])
fig, ax = plt.subplots(5, 1, figsize=(10, 16))
w = (t >= t0) & (t <= t1)
ax[0].plot(t[w], d['toe_wvx'][w], '.-', label='toe forward speed (world: truth torso + gyro + joint velocities, FK)')
ax[0].plot(t[w], -d['toe_rvx'][w], '.-', label='toe speed rel. torso (-x, joint velocities + FK)')
ax[0].plot(t[w], bs[w], '.-', label='ball speed (truth)')
ax[0].set_ylabel('m/s'); ax[0].grid(True); ax[0].legend(loc='upper left')
ax[0].plot(t[w], np.abs(d['toe_rvx'][w]), ':', color='gray')
for n in ('hip_pitch', 'knee', 'ank_pitch'):
    ax[1].plot(t[w], d['qd_' + n][w], '.-', label='kick ' + n)
for n in ('hip_pitch', 'knee', 'ank_pitch'):
    ax[1].plot(t[w], d['sqd_' + n][w], ':', label='support ' + n)
ax[1].axhline(4.82, color='k', lw=0.5); ax[1].axhline(-4.82, color='k', lw=0.5)
ax[1].set_ylabel('joint velocity (rad/s)'); ax[1].grid(True); ax[1].legend(loc='upper left', fontsize=8)
ax[2].plot(t[w], d['toe_wz'][w], label='toe height (m)')
ax[2].plot(t[w], d['bz'][w], label='ball centre height (m)')
ax[2].plot(t[w], d['pitch'][w], label='torso pitch (rad)')
ax[2].grid(True); ax[2].legend(loc='upper left')
k = t <= t1 + 1.5
ax[3].plot(t[k], d['com_f'][k], label='COM forward of the support ankle (m)')
ax[3].plot(t[k], d['cp_f'][k], label='capture point forward (m)')
ax[3].plot(t[k], d['com_l'][k], label='COM sideways (m, kicking side +)')
ax[3].plot(t[k], 0.1 * (d['yaw'][k] - d['yaw'][0]), label='torso yaw / 10 (rad)')
ax[3].axhline(0.0635, color='k', lw=0.5); ax[3].axhline(-0.0635, color='k', lw=0.5)
ax[3].grid(True); ax[3].legend(loc='upper left', fontsize=8)
dist = np.hypot(d['bx'] - d['bx'][0], d['by'] - d['by'][0])
ax[4].plot(t, dist, label='ball distance (m)')
ax[4].plot(t, bs, label='ball speed (m/s)')
ax[4].plot(t, d['state'], label='state (0 stance, 1 kick, 2 falling)')
ax[4].set_xlabel('t (s)'); ax[4].grid(True); ax[4].legend(loc='upper left')
ax[0].set_title(sys.argv[3] if len(sys.argv) > 3 else 'kick')
fig.tight_layout()
fig.savefig(sys.argv[2], dpi=70)
