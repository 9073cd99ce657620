#!/usr/bin/env python3
"""Plots a terrain walk's trace (TERRAIN_TRACE=f.csv from Tests/motion/terrain_scenario.lua) to PNG:
the torso's truth (x, height change, pitch) against the walk's feet, COM and odometry, the IMU's
capture point error and the soles' contact forces.
usage: plot_terrain.py trace.csv out.png [title] [edge_x]   (edge_x: the board's edge, m from the start)"""
import sys
import numpy as np
import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt

d = np.genfromtxt(sys.argv[1], delimiter=',', names=True)
t = d['t']
fig, ax = plt.subplots(4, 1, figsize=(11, 13), sharex=True)
ax[0].plot(t, d['x'], label='torso x (truth, from the start)')
ax[0].plot(t, d['odo_x'] - d['odo_x'][0], label='odometry x (walk)')
ax[0].plot(t, d['lx'] - d['odo_x'][0], '--', label='left foot x (walk)')
ax[0].plot(t, d['rx'] - d['odo_x'][0], ':', label='right foot x (walk)')
ax[0].plot(t, d['com_x'] - d['odo_x'][0], label='planned COM x')
if len(sys.argv) > 4:
    ax[0].axhline(float(sys.argv[4]), color='k', lw=0.8, label='board edge')
ax[0].set_ylabel('m'); ax[0].legend(loc='upper left', fontsize=8); ax[0].grid(True)
ax[1].plot(t, d['pitch'], label='torso pitch (truth)')
ax[1].plot(t, d['imu_pitch'], label='IMU pitch')
ax[1].plot(t, 0.1 * d['gyro_y'], label='gyro y / 10 (rad/s)')
ax[1].set_ylabel('rad'); ax[1].legend(loc='lower left', fontsize=8); ax[1].grid(True)
ax[2].plot(t, d['cp_ex'], label='capture point error x (IMU)')
ax[2].plot(t, d['z'], label='torso height change (truth)')
ax[2].set_ylabel('m'); ax[2].legend(loc='lower left', fontsize=8); ax[2].grid(True)
ax[3].plot(t, d['lz_force'], label='left sole force')
ax[3].plot(t, d['rz_force'], label='right sole force')
ax[3].set_ylabel('N'); ax[3].set_xlabel('s'); ax[3].legend(loc='upper left', fontsize=8); ax[3].grid(True)
ax[0].set_title(sys.argv[3] if len(sys.argv) > 3 else 'terrain')
fig.tight_layout()
fig.savefig(sys.argv[2], dpi=70)
