#!/usr/bin/env python3
"""Tunes a body's stand-up keyframes in the sim (cross-entropy search), a developer's tool.

  [ROBOT=darwin] [ROBOT_ID=N] Tools/tune/standup_tune.py NAME [GENERATIONS] [POPULATION] [SEED]

NAME is a keyframe file of the body (standup_front or standup_back). Every frame but the last (the
stance the stand-up ends in) is tuned: its duration and each `mirror` joint angle that changes from
frame to frame. A candidate is written into Config/robots/<ROBOT>/keyframes/NAME.lua and scored on
clean trials (Tools/tune/standup_trial.lua, one fresh sim each): the robot walks, is pushed over
forwards and backwards at the moments TUNE_WS (other moments than Tools/tune/standup_stats.sh's,
so that its figure stays held out) and must get up. Score per trial: 2 for up with one stand-up per
side, 1 for up after retries, less 0.02 per second taken. The file left at the end holds the best
candidate (the original is kept as NAME.lua.orig); check it with standup_stats.sh before keeping it.
"""
import os
import random
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
ROBOT = os.environ.get('ROBOT', 'op3')
FRAME = re.compile(r'\{ duration = ([-0-9.]+), hardness = ([-0-9.]+), q = \{[^}]*\}, mirror = \{(.*?)\} \}', re.S)
VALUE = re.compile(r'(\w+) = ([-0-9.]+)')


def frames_of(text):
    """[(duration, {joint: angle}), ...] and the match objects, in file order."""
    ms = list(FRAME.finditer(text))
    return [(float(m.group(1)), {k: float(v) for k, v in VALUE.findall(m.group(3))}) for m in ms], ms


def parameters(frames):
    """The tuned values: (frame index, 'duration' or joint), initial value, spread, bounds."""
    moving = [j for j in frames[0][1] if len({round(f[1][j], 4) for f in frames}) > 1]
    ps = []
    for i, (d, _) in enumerate(frames[:-1]):
        ps.append(((i, 'duration'), d, 0.08, (0.15, 1.5)))
        for j in moving:
            ps.append(((i, j), frames[i][1][j], 0.15, (-3.1, 3.1)))
    return ps


def render(text, ms, ps, x):
    """The keyframe file with the candidate x put into the frames' numbers."""
    values = {p[0]: v for p, v in zip(ps, x)}
    out, last = [], 0
    for i, m in enumerate(ms):
        out.append(text[last:m.start()])
        body = m.group(0)
        if (i, 'duration') in values:
            body = re.sub(r'duration = [-0-9.]+', 'duration = %.3f' % values[(i, 'duration')], body, count=1)
        for (fi, j), v in values.items():
            if fi == i and j != 'duration':
                body = re.sub(r'\b%s = [-0-9.]+' % j, '%s = %.3f' % (j, v), body, count=1)
        out.append(body)
        last = m.end()
    out.append(text[last:])
    return ''.join(out)


def trial(direction, w, rid):
    """One clean stand-up trial: 'up1' (one stand-up per side), 'up', 'down' or 'nofall', and the time."""
    env = dict(os.environ, ROBOT=ROBOT, DIR=str(direction), W=str(w))
    cmd = ('source Tests/motion/kick_sim.sh; kick_sim_run %d "$KICK_LOGS/tune_main.log" '
           'timeout 120 ./run_repl Tools/tune/standup_trial.lua' % rid)
    out = subprocess.run(['bash', '-c', cmd], cwd=ROOT, env=env, capture_output=True, text=True).stdout
    for line in out.splitlines():
        m = re.match(r'RESULT dir \S+ W \S+: (\w+) attempts front (\d+) back (\d+) after ([0-9.]+) s', line)
        if m:
            kind, front, back, t = m.group(1), int(m.group(2)), int(m.group(3)), float(m.group(4))
            if kind == 'up' and front <= 1 and back <= 1:
                kind = 'up1'
            return kind, t
    return 'down', 20.0


def score(cases, rid):
    s, ups = 0.0, 0
    for direction, w in cases:
        kind, t = trial(direction, w, rid)
        if kind in ('up1', 'up'):
            ups += 1
            s += (2.0 if kind == 'up1' else 1.0) - 0.02 * t
    return s, ups


def main():
    if len(sys.argv) < 2:
        print(__doc__)
        return 2
    name = sys.argv[1]
    gens = int(sys.argv[2]) if len(sys.argv) > 2 else 6
    pop = int(sys.argv[3]) if len(sys.argv) > 3 else 8
    random.seed(int(sys.argv[4]) if len(sys.argv) > 4 else 1)
    rid = int(os.environ.get('ROBOT_ID', '9350'))
    path = os.path.join(ROOT, 'Config', 'robots', ROBOT, 'keyframes', name + '.lua')
    text = open(path).read()
    if not os.path.exists(path + '.orig'):
        open(path + '.orig', 'w').write(text)
    frames, ms = frames_of(text)
    if len(frames) < 2:
        print('%s: no keyframes in the form { duration = .., hardness = .., q = {..}, mirror = {..} }' % path)
        return 2
    ps = parameters(frames)
    ws = [float(w) for w in os.environ.get('TUNE_WS', '1.9 2.05 2.2 2.35 2.5 2.65 2.8').split()]
    cases = [(1, w) for w in ws] + [(-1, w) for w in ws]
    mean = [p[1] for p in ps]
    spread = [p[2] for p in ps]

    def evaluate(x):
        open(path, 'w').write(render(text, ms, ps, x))
        return score(cases, rid)

    best = (evaluate(mean), mean)
    print('start: score %.2f, up %d/%d' % (best[0][0], best[0][1], len(cases)), flush=True)
    for g in range(gens):
        results = []
        for _ in range(pop):
            x = [min(max(random.gauss(m, s), p[3][0]), p[3][1]) for m, s, p in zip(mean, spread, ps)]
            r = evaluate(x)
            results.append((r, x))
            if r[0] > best[0][0]:
                best = (r, x)
        results.sort(key=lambda r: -r[0][0])
        elite = [x for _, x in results[:max(2, pop // 4)]]
        for k in range(len(ps)):
            vals = [e[k] for e in elite]
            m = sum(vals) / len(vals)
            sd = (sum((v - m) ** 2 for v in vals) / len(vals)) ** 0.5
            mean[k] = 0.5 * mean[k] + 0.5 * m
            spread[k] = max(0.5 * spread[k] + 0.5 * sd, 0.01)
        print('generation %d: best %.2f (up %d/%d), overall %.2f (up %d)' % (
            g + 1, results[0][0][0], results[0][0][1], len(cases), best[0][0], best[0][1]), flush=True)
    open(path, 'w').write(render(text, ms, ps, best[1]))
    print('best: score %.2f, up %d/%d; written to %s' % (best[0][0], best[0][1], len(cases), path))
    return 0


if __name__ == '__main__':
    sys.exit(main())
