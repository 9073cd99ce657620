#!/usr/bin/env python3
"""The frames of two sim camera renderers compared: files of `sim_camera_frames --raw FILE` (each
scene's clean frame, then its realistic one, YUYV), written by two builds on the same scenes.
Prints, for the clean and for the realistic frames, the share of pixels that differ (in RGB, as a
PNG shows them), the mean absolute difference per RGB channel, the largest one, and the mean
brightness and its spread over a frame in either file (the look's statistics).
  .venv/bin/python Tools/bench/camera_diff.py A.raw B.raw [WIDTH HEIGHT]      (default 640 480)
Exits 1 when the files' sizes differ."""
import sys

import numpy as np


def rgb(yuyv, w, h):
    """RGB (int) of YUYV frames of shape (n, h, w * 2), BT.601 as the sim's PNG writer."""
    y = yuyv[..., 0::2].astype(np.float64)
    u = np.repeat(yuyv[..., 1::4], 2, axis=-1).astype(np.float64) - 128
    v = np.repeat(yuyv[..., 3::4], 2, axis=-1).astype(np.float64) - 128
    out = np.stack([y + 1.402 * v, y - 0.344136 * u - 0.714136 * v, y + 1.772 * u], axis=-1)
    return np.clip(np.rint(out), 0, 255).astype(np.int16)


def main():
    if len(sys.argv) not in (3, 5):
        sys.exit(__doc__)
    w, h = (int(sys.argv[3]), int(sys.argv[4])) if len(sys.argv) == 5 else (640, 480)
    a = np.fromfile(sys.argv[1], dtype=np.uint8)
    b = np.fromfile(sys.argv[2], dtype=np.uint8)
    if a.size != b.size or a.size % (2 * w * h * 2):
        print(f"sizes differ or are not whole scenes: {a.size} and {b.size} bytes")
        return 1
    a = a.reshape(-1, 2, h, w * 2)
    b = b.reshape(-1, 2, h, w * 2)
    for k, name in enumerate(("clean", "realistic")):
        fa, fb = a[:, k], b[:, k]
        same_bytes = np.array_equal(fa, fb)
        ra, rb = rgb(fa, w, h), rgb(fb, w, h)
        d = np.abs(ra - rb)
        px = np.any(d > 0, axis=-1)
        ya, yb = fa[..., 0::2].astype(np.float64), fb[..., 0::2].astype(np.float64)
        print(f"{name}: {fa.shape[0]} frames, bytes {'identical' if same_bytes else 'differ'}; "
              f"pixels differing {100 * px.mean():.3f}%, mean abs difference {d.mean():.4f} RGB levels per channel, "
              f"max {d.max()}; luma mean {ya.mean():.3f} / {yb.mean():.3f}, "
              f"luma sd within a frame {ya.std(axis=(1, 2)).mean():.3f} / {yb.std(axis=(1, 2)).mean():.3f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
