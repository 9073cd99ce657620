#!/usr/bin/env python3
"""Draws a match's trace (Tools/match/referee.lua with HRP_MATCH_TRACE set) as panels of PLAYING time, and
prints what each robot did: falls, seconds fallen, seconds near another robot, ball touches.

    Tools/plot/plot_match.py TRACE.txt [SECONDS_PER_PANEL (30)]   -> TRACE.png next to it

A trace line: "t state bx by", per robot the truth "x y yaw fallen role" (role -1: penalized), then
(traces with a "# robots N" header) per robot its own view "px py pyaw ball_x ball_y ball_age
body_state" in the same frame. Team 1 is the first half of the robots. Panels run left to right, top to bottom, one per SECONDS_PER_PANEL of
PLAYING: team 1 blue (player 1 dark), team 2 red (player 1 dark), the ball orange, falls as crosses,
each robot's end position as a circle with its heading.
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plot_paths as pp  # noqa: E402  (the field, the rasteriser and the PNG writer)

PLAYING = 3  # GameFSM/packet.lua STATE.playing
COLOURS = {(1, 1): (20, 40, 200), (1, 2): (110, 160, 255), (2, 1): (200, 20, 20), (2, 2): (255, 130, 130),
           (1, 3): (0, 200, 220), (1, 4): (120, 0, 200), (2, 3): (240, 200, 0), (2, 4): (160, 90, 0)}
ROLE_NAMES = {-1: 'penalized', 0: 'none', 1: 'striker', 2: 'supporter', 3: 'defender', 4: 'goalkeeper'}


def load(path):
    rows, n = [], None
    with open(path) as f:
        for ln in f:
            p = ln.split()
            if ln.startswith('# robots'):
                n = int(p[2])
            elif len(p) >= 9:
                rows.append([float(v) for v in p])
    a = np.array(rows)
    return a, n if n else (a.shape[1] - 4) // 5


def view(a, n, i):
    """px, py, pyaw, ball_x, ball_y, ball_age, body_state of robot i's own view, or None (old traces)"""
    c = 4 + 5 * n + 7 * i
    return None if a.shape[1] < 4 + 12 * n else tuple(a[:, c + k] for k in range(7))


def robot(a, i):
    """x, y, yaw, fallen, role of robot i (0-based)"""
    c = 4 + 5 * i
    return a[:, c], a[:, c + 1], a[:, c + 2], a[:, c + 3], a[:, c + 4]


def panel(a, n, sel):
    img = np.zeros((pp.H, pp.W, 3), np.uint8)
    pp.field(img)
    rows = a[sel]
    if len(rows) < 2:
        return img
    for i in range(n):
        team, player = (1, i + 1) if i < n // 2 else (2, i - n // 2 + 1)
        col = COLOURS.get((team, player), (255, 255, 255))
        x, y, yaw, fallen, role = robot(rows, i)
        for k in range(1, len(rows)):
            if role[k] >= 0 and role[k - 1] >= 0 and abs(x[k] - x[k - 1]) + abs(y[k] - y[k - 1]) < 0.5:
                pp.line(img, x[k - 1], y[k - 1], x[k], y[k], col, 1)
        for k in np.nonzero((fallen[1:] > 0) & (fallen[:-1] == 0))[0] + 1:
            pp.line(img, x[k] - 0.1, y[k] - 0.1, x[k] + 0.1, y[k] + 0.1, (0, 0, 0), 2)
            pp.line(img, x[k] - 0.1, y[k] + 0.1, x[k] + 0.1, y[k] - 0.1, (0, 0, 0), 2)
        pp.circle(img, x[-1], y[-1], 0.12, col, 2)
        pp.line(img, x[-1], y[-1], x[-1] + 0.3 * np.cos(yaw[-1]), y[-1] + 0.3 * np.sin(yaw[-1]), col, 2)
    bx, by = rows[:, 2], rows[:, 3]
    for k in range(1, len(rows)):
        if abs(bx[k] - bx[k - 1]) + abs(by[k] - by[k - 1]) < 0.5:  # not a placement by the referee
            pp.line(img, bx[k - 1], by[k - 1], bx[k], by[k], (255, 150, 0), 1)
    pp.circle(img, bx[-1], by[-1], 0.08, (255, 150, 0), 2)
    return img


def summary(a, n):
    t, state = a[:, 0], a[:, 1]
    dt = np.diff(t, append=t[-1])
    play = state == PLAYING
    print('PLAYING %.0f s of %.0f s' % ((dt * play).sum(), t[-1] - t[0]))
    pos = [robot(a, i) for i in range(n)]
    for i in range(n):
        team, player = (1, i + 1) if i < n // 2 else (2, i - n // 2 + 1)
        x, y, _, fallen, role = pos[i]
        falls = int(((fallen[1:] > 0) & (fallen[:-1] == 0) & play[1:]).sum())
        down = (dt * play * (fallen > 0)).sum()
        close = np.zeros(len(t), bool)  # torsos closer than 0.35 m to another robot
        for j in range(n):
            if j != i:
                close |= np.hypot(x - pos[j][0], y - pos[j][1]) < 0.35
        near_ball = np.hypot(x - a[:, 2], y - a[:, 3]) < 0.25
        roles = {ROLE_NAMES.get(int(r), str(r)): (dt * play * (role == r)).sum() for r in np.unique(role)}
        belief = ''
        v = view(a, n, i)
        if v is not None:  # the pose belief's error while playing and not penalized
            on = play & (role >= 0)
            err = np.hypot(v[0] - x, v[1] - y)[on]
            if len(err):
                belief = '; pose error median %.2f m, p95 %.2f m, over 1 m %.0f s' % (
                    np.median(err), np.percentile(err, 95), (dt[on] * (err > 1.0)).sum())
        print('%d/%d falls %d, fallen %.0f s, near a robot %.0f s, at the ball %.0f s; %s%s' % (
            team, player, falls, down, (dt * play * close).sum(), (dt * play * near_ball).sum(),
            ' '.join('%s=%.0f' % kv for kv in roles.items()), belief))


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    path = sys.argv[1]
    span = float(sys.argv[2]) if len(sys.argv) > 2 else 30.0
    a, n = load(path)
    summary(a, n)
    t, play = a[:, 0], a[:, 1] == PLAYING
    # cumulative PLAYING time decides the panel: each panel holds `span` s of play
    dt = np.diff(t, prepend=t[0])
    clock = np.cumsum(dt * play)
    k = (clock // span).astype(int)
    # (a last panel of a row or two, the play clock's final tick, is left out)
    panels = [panel(a, n, play & (k == j)) for j in range(k[play].max() + 1)
              if (play & (k == j)).sum() >= 2] if play.any() else []
    cols = 2
    while len(panels) % cols:
        panels.append(np.full_like(panels[0], 255))
    grid = np.vstack([np.hstack(panels[r:r + cols]) for r in range(0, len(panels), cols)])
    out = path.rsplit('.', 1)[0] + '.png'
    pp.write_png(out, grid)
    print(out)


if __name__ == '__main__':
    main()
