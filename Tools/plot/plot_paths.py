#!/usr/bin/env python3
"""Draws the robot's and the ball's paths of scoring runs on the field, one PNG per trace.

    Tools/plot/plot_paths.py TRACE.txt [...]     -> TRACE.png next to each trace

A trace is what Tests/scenarios/score_one.lua writes with TRUTH_LOG set: one line per step,
"t x y yaw bx by fallen px py pyaw wbx wby ball_age body motion". Drawn: field lines and goals
(white/yellow), the robot's true path (blue, a tick every 10 s, red crosses where it had fallen),
its own pose estimate (light blue), the ball's true path (orange) and the start positions (circles).
numpy only (no matplotlib): a small rasteriser and a PNG writer.
"""
import struct
import sys
import zlib

import numpy as np

SCALE = 80  # pixels per metre
MARGIN = 0.7  # m around the field lines
FIELD_L, FIELD_W = 9.0, 6.0
W = int((FIELD_L + 2 * MARGIN) * SCALE)
H = int((FIELD_W + 2 * MARGIN) * SCALE)


def px(x, y):
    return (x + FIELD_L / 2 + MARGIN) * SCALE, (FIELD_W / 2 + MARGIN - y) * SCALE


def dot(img, x, y, colour, r=1):
    cx, cy = px(x, y)
    cx, cy = int(round(cx)), int(round(cy))
    img[max(0, cy - r):max(0, cy + r + 1), max(0, cx - r):max(0, cx + r + 1)] = colour


def line(img, x0, y0, x1, y1, colour, r=1):
    n = int(max(abs(x1 - x0), abs(y1 - y0)) * SCALE * 2) + 1
    for s in np.linspace(0.0, 1.0, n):
        dot(img, x0 + (x1 - x0) * s, y0 + (y1 - y0) * s, colour, r)


def circle(img, x, y, rad, colour, r=1):
    a = np.linspace(0, 2 * np.pi, int(rad * SCALE * 8) + 16)
    for u, v in zip(x + rad * np.cos(a), y + rad * np.sin(a)):
        dot(img, u, v, colour, r)


def field(img):
    img[:] = (30, 120, 40)
    white = (235, 235, 235)
    hl, hw = FIELD_L / 2, FIELD_W / 2
    for a, b, c, d in [(-hl, -hw, hl, -hw), (hl, -hw, hl, hw), (hl, hw, -hl, hw), (-hl, hw, -hl, -hw),
                       (0, -hw, 0, hw)]:
        line(img, a, b, c, d, white)
    circle(img, 0, 0, 0.75, white)
    for sx in (-1, 1):  # goal areas (1 m deep, 3 m wide) and penalty marks (1.5 m)
        line(img, sx * hl, -1.5, sx * (hl - 1), -1.5, white)
        line(img, sx * (hl - 1), -1.5, sx * (hl - 1), 1.5, white)
        line(img, sx * (hl - 1), 1.5, sx * hl, 1.5, white)
        dot(img, sx * (hl - 1.5), 0, white, 2)
        # goal: posts at y = +-1.3, 0.6 m deep
        yellow = (240, 220, 40)
        line(img, sx * hl, -1.3, sx * (hl + 0.6), -1.3, yellow, 2)
        line(img, sx * (hl + 0.6), -1.3, sx * (hl + 0.6), 1.3, yellow, 2)
        line(img, sx * (hl + 0.6), 1.3, sx * hl, 1.3, yellow, 2)


def write_png(path, img):
    h, w, _ = img.shape
    raw = b''.join(b'\x00' + img[y].astype(np.uint8).tobytes() for y in range(h))

    def chunk(kind, data):
        c = struct.pack('>I', len(data)) + kind + data
        return c + struct.pack('>I', zlib.crc32(kind + data) & 0xffffffff)

    with open(path, 'wb') as f:
        f.write(b'\x89PNG\r\n\x1a\n')
        f.write(chunk(b'IHDR', struct.pack('>IIBBBBB', w, h, 8, 2, 0, 0, 0)))
        f.write(chunk(b'IDAT', zlib.compress(raw, 6)))
        f.write(chunk(b'IEND', b''))


def plot(trace):
    rows = []
    with open(trace) as f:
        for ln in f:
            if ln.startswith('#') or ln.startswith('post') or not ln.strip():
                continue
            p = ln.split()
            rows.append([float(v) for v in p[:13]])
    img = np.zeros((H, W, 3), np.uint8)
    field(img)
    if rows:
        a = np.array(rows)
        t, x, y, yaw, bx, by, fallen, pxe, pye = (a[:, i] for i in range(9))
        for i in range(1, len(a)):
            line(img, pxe[i - 1], pye[i - 1], pxe[i], pye[i], (150, 200, 255), 0)
        for i in range(1, len(a)):
            line(img, bx[i - 1], by[i - 1], bx[i], by[i], (255, 150, 0), 1)
            line(img, x[i - 1], y[i - 1], x[i], y[i], (30, 60, 230), 1)
        for i in range(len(a)):
            if fallen[i] > 0:
                line(img, x[i] - 0.06, y[i] - 0.06, x[i] + 0.06, y[i] + 0.06, (230, 0, 0), 1)
                line(img, x[i] - 0.06, y[i] + 0.06, x[i] + 0.06, y[i] - 0.06, (230, 0, 0), 1)
        for k in range(1, int(t[-1] // 10) + 1):  # robot heading every 10 s
            i = int(np.searchsorted(t, 10.0 * k))
            if i < len(a):
                dot(img, x[i], y[i], (255, 255, 255), 3)
                line(img, x[i], y[i], x[i] + 0.25 * np.cos(yaw[i]), y[i] + 0.25 * np.sin(yaw[i]), (0, 0, 0), 1)
        circle(img, x[0], y[0], 0.12, (30, 60, 230), 2)
        line(img, x[0], y[0], x[0] + 0.3 * np.cos(yaw[0]), y[0] + 0.3 * np.sin(yaw[0]), (30, 60, 230), 2)
        circle(img, bx[0], by[0], 0.09, (255, 150, 0), 2)
    out = trace.rsplit('.', 1)[0] + '.png'
    write_png(out, img)
    return out


if __name__ == '__main__':
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    for tr in sys.argv[1:]:
        print(plot(tr))
