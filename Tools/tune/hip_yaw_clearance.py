#!/usr/bin/env python3
"""Where the legs of a body touch each other as the hip yaws turn (the self-collision the sim
models between the URDF's collision boxes), at the walk's stance (the body's walk config through the leg IK): a map
over each foot's toe-out (rad, positive = the toe turned outward), and the feet's relative yaw
(the sum of both toe-outs) at which the legs first touch toed out and toed in with both hips
turned alike -- the numbers behind a walk config's stepLimitA and turnToeIn.
usage: [ROBOT=op3] Tools/tune/hip_yaw_clearance.py     (run from the project's root, Run/env.sh sourced)"""
import json
import subprocess
import xml.etree.ElementTree as ET
import numpy as np

cfg = json.loads(subprocess.check_output(['luajit', '-e', """
local Config = require('Config')
local robot = Config.load('robot')
local walk = require('Motion.walk').new(Config.load('walk'), require('kinematics').load()):bind(robot)
walk:advance(robot.period)
local q, out = {}, {}
for i = 1, #robot.joints do q[i] = 0 end
walk:joint_angles(q, nil, robot.period)
for i, name in ipairs(robot.joints) do out[#out + 1] = string.format('"%s": %.17g', name, q[i]) end
print(string.format('{"urdf": "%s", "lleg": ["%s"], "rleg": ["%s"], "q": {%s}}', Config.robot_file(robot.description),
  table.concat(robot.groups.lleg, '", "'), table.concat(robot.groups.rleg, '", "'), table.concat(out, ', ')))"""]))
urdf = ET.parse(cfg['urdf']).getroot()


def rpy(r, p, y):
    cr, sr, cp, sp, cy, sy = np.cos(r), np.sin(r), np.cos(p), np.sin(p), np.cos(y), np.sin(y)
    return (np.array([[cy, -sy, 0], [sy, cy, 0], [0, 0, 1]]) @ np.array([[cp, 0, sp], [0, 1, 0], [-sp, 0, cp]])
            @ np.array([[1, 0, 0], [0, cr, -sr], [0, sr, cr]]))


def frame(xyz, rot):
    m = np.eye(4)
    m[:3, :3], m[:3, 3] = rot, xyz
    return m


def nums(s, default='0 0 0'):
    return [float(v) for v in (s or default).split()]


def axis_angle(a, q):
    a = np.array(a) / np.linalg.norm(a)
    k = np.array([[0, -a[2], a[1]], [a[2], 0, -a[0]], [-a[1], a[0], 0]])
    return np.eye(3) + np.sin(q) * k + (1 - np.cos(q)) * k @ k


joints = {}   # child link -> (joint, parent link, origin, axis)
for j in urdf.findall('joint'):
    o, ax = j.find('origin'), j.find('axis')
    joints[j.find('child').get('link')] = (j.get('name'), j.find('parent').get('link'),
                                           frame(nums(o.get('xyz')), rpy(*nums(o.get('rpy')))),
                                           nums(ax.get('xyz')) if ax is not None else None)
boxes = {}    # link -> [(origin, half size)]
for link in urdf.findall('link'):
    for c in link.findall('collision'):
        o, b = c.find('origin'), c.find('geometry/box')
        if b is not None:
            boxes.setdefault(link.get('name'), []).append(
                (frame(nums(o.get('xyz')), rpy(*nums(o.get('rpy')))), np.array(nums(b.get('size'))) / 2))


def pose(link, q):
    if link not in joints:
        return np.eye(4)
    name, parent, origin, axis = joints[link]
    m = pose(parent, q) @ origin
    return m @ frame([0, 0, 0], axis_angle(axis, q.get(name, 0))) if axis else m


def overlap(a, ha, b, hb):
    """Separating axis test of two oriented boxes."""
    ra, rb, t = a[:3, :3], b[:3, :3], b[:3, 3] - a[:3, 3]
    axes = [ra[:, i] for i in range(3)] + [rb[:, i] for i in range(3)]
    axes += [np.cross(ra[:, i], rb[:, j]) for i in range(3) for j in range(3)]
    for ax in axes:
        n = np.linalg.norm(ax)
        if n < 1e-9:
            continue
        ax = ax / n
        if sum(ha[i] * abs(ra[:, i] @ ax) + hb[i] * abs(rb[:, i] @ ax) for i in range(3)) < abs(t @ ax):
            return False
    return True


def leg_links(joint_names):
    return [child for child, j in joints.items() if j[0] in joint_names and child in boxes]


left, right = leg_links(cfg['lleg']), leg_links(cfg['rleg'])
hip_l, hip_r = cfg['lleg'][0], cfg['rleg'][0]
# a toe-out turns the left foot about +z and the right one about -z: the hip yaw's angle along its axis
sign_l = np.sign(joints[[c for c, j in joints.items() if j[0] == hip_l][0]][3][2])
sign_r = -np.sign(joints[[c for c, j in joints.items() if j[0] == hip_r][0]][3][2])


def touching(out_l, out_r):
    q = dict(cfg['q'])
    q[hip_l], q[hip_r] = sign_l * out_l, sign_r * out_r
    hits = set()
    for a in left:
        for b in right:
            if any(overlap(pose(a, q) @ fa, ha, pose(b, q) @ fb, hb) for fa, ha in boxes[a] for fb, hb in boxes[b]):
                hits.add(a.split('_', 1)[1].replace('_link', ''))
    return hits


vals = np.round(np.arange(-0.6, 0.61, 0.1), 2)
print('toe-out left (rows) x right (columns), rad; the links that touch (a part of their name)')
print('      ' + ' '.join('%6.1f' % v for v in vals))
for a in vals:
    print('%5.1f ' % a + ' '.join((','.join(sorted(h[:4] for h in touching(a, b))) or '.').center(6) for b in vals))
for sign, what in ((1, 'toed out'), (-1, 'toed in')):
    x = 0.0
    while x < 1.5 and not touching(sign * x / 2, sign * x / 2):
        x += 0.01
    print('both hips alike, %s: the legs touch at a relative yaw of %.2f rad' % (what, x))
