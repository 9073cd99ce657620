#!/usr/bin/env python3
"""The capture point error's distribution in normal play against pushes, to place the capture
terms' activation (walk config stepAdjust.activation; Player/Motion/capture.lua).
usage: capture_stats.py OUT.png PLAY_DIR [PUSH.csv ...]
PLAY_DIR: capture_*.txt from a scoring run (Tests/scenarios/score_test.sh with CAPTURE_LOGS=1:
t ex ey walking state per motion tick); PUSH.csv: Tools/tune/push_trace.lua's logs (push at t=0).
Prints, for the ticks the robot walks, the percentiles of |ey|, |ex| and |e|, and for each push the
peak |ey| in its first 0.6 s and when it first went beyond 0.02..0.05 m; plots both histograms."""
import glob
import os
import sys
import numpy as np
import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt


WALK = 3  # Motion.STATES: relax sit stance walk ... (0-based in the motion shm)


def play(dirname):
    rows = []
    for f in sorted(glob.glob(os.path.join(dirname, 'capture_*.txt'))):
        d = np.loadtxt(f, comments='#', ndmin=2)
        if d.size:
            rows.append(d[(d[:, 3] == 1) & (d[:, 4] == WALK)])  # walking ticks only (not falling)
    if not rows:
        sys.exit('capture_stats: no capture_*.txt in ' + dirname)
    return np.vstack(rows)


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    out, pdir, pushes = sys.argv[1], sys.argv[2], sys.argv[3:]
    d = play(pdir)
    ex, ey = np.abs(d[:, 1]), np.abs(d[:, 2])
    en = np.hypot(ex, ey)
    qs = [50, 90, 99, 99.9, 100]
    print('play: %d walking ticks (%.0f s) from %s' % (len(d), len(d) * 0.008, pdir))
    for name, v in (('|ey|', ey), ('|ex|', ex), ('|e|', en)):
        print('  %-5s ' % name + '  '.join('p%g %.4f' % (q, np.percentile(v, q)) for q in qs))
    for th in (0.02, 0.03, 0.04, 0.05):
        print('  beyond %.2f m: |ey| %.3f%%  |ex| %.3f%%  of walking ticks' % (
            th, 100 * np.mean(ey > th), 100 * np.mean(ex > th)))
    fig, ax = plt.subplots(2, 1, figsize=(10, 9))
    bins = np.linspace(0, 0.12, 121)
    ax[0].hist(ey, bins=bins, alpha=0.6, label='|ey| play (%d ticks)' % len(d), log=True)
    ax[0].hist(ex, bins=bins, alpha=0.6, label='|ex| play', log=True)
    for path in pushes:
        p = np.genfromtxt(path, delimiter=',', names=True)
        w = (p['t'] >= 0) & (p['t'] <= 0.6)
        pey = np.abs(p['cp_ey'][w])
        first = []
        for th in (0.02, 0.03, 0.04, 0.05):
            i = np.nonzero(pey > th)[0]
            first.append('%.2f:%s' % (th, '%.3f s' % p['t'][w][i[0]] if len(i) else 'never'))
        print('push %s: peak |ey| %.4f m in 0.6 s; first beyond %s' % (path, pey.max(), ' '.join(first)))
        ax[0].hist(pey, bins=bins, alpha=0.5, label='|ey| push ' + os.path.basename(os.path.dirname(path)), log=True,
                   histtype='step', linewidth=2)
        ax[1].plot(p['t'], p['cp_ey'], label=os.path.basename(os.path.dirname(path)))
    ax[0].set_xlabel('capture point error (m)'); ax[0].set_ylabel('ticks'); ax[0].legend(fontsize=8); ax[0].grid(True)
    ax[1].axvspan(0, 0.1, color='red', alpha=0.2)
    for th in (0.02, 0.03, 0.04):
        ax[1].axhline(th, color='grey', linestyle=':')
    ax[1].set_xlabel('t after the push (s)'); ax[1].set_ylabel('ey (m)'); ax[1].grid(True)
    if pushes:
        ax[1].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out, dpi=80)
    print('wrote ' + out)


main()
