#!/usr/bin/env python3
"""Draws where on the field the robots fell, one marker per fall coloured by its cause (the fall census,
Tools/match/census.lua), with an arrow along the measured velocity at the tip; several CSVs (matches, soaks)
go into one plot.

    Tools/plot/plot_falls.py FALLS.csv [...] [-o OUT.png]   -> the first CSV's name with .png by default

A CSV is what Tools/match/referee.lua (HRP_MATCH_FALLS) and Tests/soak/soak_play.lua (SOAK_FALLS) write:
robot,name,t,cause,causes,x,y,yaw,cmd_vx,cmd_vy,cmd_va,vx,vy,va,tilt,state (field frame, m, rad).
"""
import argparse
import csv
import math
import os

import matplotlib

matplotlib.use('Agg')
import matplotlib.pyplot as plt  # noqa: E402

FIELD_L, FIELD_W = 9.0, 6.0  # Config/platforms/Sim/sim.lua: the KidSize field
CAUSES = ['push', 'standup', 'kick', 'goal', 'contact', 'ball', 'turn', 'walking', 'standing']
NAMES = {'push': 'after a push', 'standup': 'failed stand-up', 'kick': 'kick', 'goal': 'goal frame / net',
         'contact': 'robot contact',
         'ball': 'ball at the feet', 'turn': 'turn / sideways step', 'walking': 'walking straight',
         'standing': 'standing'}
COLOURS = {'push': 'black', 'standup': 'purple', 'kick': 'orange', 'goal': 'white', 'contact': 'red', 'ball': 'gold',
           'turn': 'deepskyblue', 'walking': 'blue', 'standing': 'grey'}


def field(ax):
    ax.set_facecolor((0.12, 0.47, 0.16))
    hl, hw = FIELD_L / 2, FIELD_W / 2
    kw = dict(color='white', lw=1)
    ax.plot([-hl, hl, hl, -hl, -hl], [-hw, -hw, hw, hw, -hw], **kw)
    ax.plot([0, 0], [-hw, hw], **kw)
    ax.add_patch(plt.Circle((0, 0), 0.75, fill=False, **kw))
    for sx in (-1, 1):
        ax.plot([sx * hl, sx * (hl - 1), sx * (hl - 1), sx * hl], [-1.5, -1.5, 1.5, 1.5], **kw)
        ax.plot([sx * hl, sx * (hl + 0.6), sx * (hl + 0.6), sx * hl], [-1.3, -1.3, 1.3, 1.3], color='yellow', lw=2)
    ax.set_xlim(-hl - 0.8, hl + 0.8)
    ax.set_ylim(-hw - 0.8, hw + 0.8)
    ax.set_aspect('equal')


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('csv', nargs='+')
    ap.add_argument('-o', '--out')
    a = ap.parse_args()
    falls = []
    for path in a.csv:
        with open(path) as f:
            falls += list(csv.DictReader(f))
    fig, ax = plt.subplots(figsize=(10, 7))
    field(ax)
    counts = {}
    for r in falls:
        counts[r['cause']] = counts.get(r['cause'], 0) + 1
    for c in CAUSES:
        rs = [r for r in falls if r['cause'] == c]
        if not rs:
            continue
        xs, ys = [float(r['x']) for r in rs], [float(r['y']) for r in rs]
        ax.scatter(xs, ys, c=COLOURS[c], s=40, marker='x' if c in ('walking', 'standing') else 'o',
                   label='%s (%d)' % (NAMES[c], counts[c]), zorder=3)
        for r, x, y in zip(rs, xs, ys):  # the measured velocity, field frame, 1 s of it
            yaw, vx, vy = float(r['yaw']), float(r['vx']), float(r['vy'])
            dx, dy = math.cos(yaw) * vx - math.sin(yaw) * vy, math.sin(yaw) * vx + math.cos(yaw) * vy
            if math.hypot(dx, dy) > 0.02:
                ax.arrow(x, y, dx, dy, color=COLOURS[c], width=0.005, head_width=0.06, zorder=2)
    ax.legend(loc='upper left', fontsize=8, ncol=2, framealpha=0.8)
    ax.set_title('%d falls (%s)' % (len(falls), ', '.join(os.path.basename(p) for p in a.csv)))
    out = a.out or os.path.splitext(a.csv[0])[0] + '.png'
    fig.savefig(out, dpi=80, bbox_inches='tight')
    print('falls plot: %s (%d falls)' % (out, len(falls)))


if __name__ == '__main__':
    main()
