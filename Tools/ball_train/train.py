#!/usr/bin/env python3
"""Trains the white-ball classifier: a small MLP (NFEAT -> hidden ReLU -> sigmoid) on the samples
Tools/ball_train/samples.lua wrote, with numpy only (CPU, seconds), and writes the model file the
vision reads (Modules/balldetect: bd_mlp_load).

  train.py SAMPLES OUT [--hidden 16] [--epochs 60] [--margin 1.4] [--seed 1]
"""
import argparse
import sys

import numpy as np

NFEAT = 16 * 16 + 2 * 4 * 4 + 3  # balldetect.h BD_NFEAT


def load(path):
    raw = np.fromfile(path, dtype=np.uint8)
    rec = 1 + 4 * NFEAT
    if raw.size == 0 or raw.size % rec:
        sys.exit(f"{path}: {raw.size} bytes is not a whole number of {rec}-byte samples")
    raw = raw.reshape(-1, rec)
    y = raw[:, 0].astype(np.float32)
    x = raw[:, 1:].copy().view(np.float32)
    return x, y


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("samples")
    ap.add_argument("out")
    ap.add_argument("--hidden", type=int, default=16)
    ap.add_argument("--epochs", type=int, default=60)
    ap.add_argument("--margin", type=float, default=1.4)
    ap.add_argument("--seed", type=int, default=1)
    a = ap.parse_args()
    x, y = load(a.samples)
    rng = np.random.default_rng(a.seed)
    idx = rng.permutation(len(y))
    nval = len(y) // 6
    val, tr = idx[:nval], idx[nval:]
    print(f"{len(y)} samples ({int(y.sum())} ball), {len(tr)} to train, {nval} to validate")
    H = a.hidden
    W1 = (rng.standard_normal((H, NFEAT)) * np.sqrt(2 / NFEAT)).astype(np.float32)
    b1 = np.zeros(H, np.float32)
    w2 = (rng.standard_normal(H) * np.sqrt(1 / H)).astype(np.float32)
    b2 = np.float32(0)
    params = [W1, b1, w2, np.array([b2], np.float32)]
    m = [np.zeros_like(p) for p in params]
    v = [np.zeros_like(p) for p in params]
    # both classes weigh the same in the loss, whatever their counts
    pos = max(1.0, float(y[tr].sum()))
    neg = max(1.0, float(len(tr) - y[tr].sum()))
    cw = np.where(y > 0, len(tr) / (2 * pos), len(tr) / (2 * neg)).astype(np.float32)
    lr, l2, bs, t = 3e-3, 1e-4, 256, 0

    def forward(xb):
        h = np.maximum(0, xb @ params[0].T + params[1])
        z = h @ params[2] + params[3][0]
        return h, 1 / (1 + np.exp(-np.clip(z, -30, 30)))

    for ep in range(a.epochs):
        order = rng.permutation(tr)
        for k in range(0, len(order), bs):
            bi = order[k:k + bs]
            xb, yb, wb = x[bi], y[bi], cw[bi]
            h, p = forward(xb)
            dz = (p - yb) * wb / len(bi)
            g_w2 = h.T @ dz + l2 * params[2]
            g_b2 = np.array([dz.sum()], np.float32)
            dh = np.outer(dz, params[2]) * (h > 0)
            g_W1 = dh.T @ xb + l2 * params[0]
            g_b1 = dh.sum(0)
            t += 1
            for i, g in enumerate([g_W1, g_b1, g_w2, g_b2]):
                m[i] = 0.9 * m[i] + 0.1 * g
                v[i] = 0.999 * v[i] + 0.001 * g * g
                mh, vh = m[i] / (1 - 0.9 ** t), v[i] / (1 - 0.999 ** t)
                params[i] -= (lr * mh / (np.sqrt(vh) + 1e-8)).astype(np.float32)
        if ep % 10 == 9 or ep == a.epochs - 1:
            for name, s in (("train", tr), ("validation", val)):
                _, p = forward(x[s])
                yy = y[s] > 0
                pp = p >= 0.5
                rec = (pp & yy).sum() / max(1, yy.sum())
                fpr = (pp & ~yy).sum() / max(1, (~yy).sum())
                print(f"epoch {ep + 1}: {name}: ball recall {100 * rec:.1f}%, not-ball taken {100 * fpr:.2f}%")
    with open(a.out, "w") as f:
        f.write(f"hrp-ball-mlp 1 {NFEAT} {H} {a.margin}\n")
        for row in params[0]:
            f.write(" ".join(f"{z:.6g}" for z in row) + "\n")
        for arr in (params[1], params[2], params[3]):
            f.write(" ".join(f"{z:.6g}" for z in arr) + "\n")
    print(f"wrote {a.out}")


if __name__ == "__main__":
    main()
