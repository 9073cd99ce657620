#!/usr/bin/env python3
"""Writes the simulated robot's URDF from the reference data.

    Platforms/Sim/gen_urdf.py [REFERENCE] [ROBOT_LUA] [OUT]

defaults: /work/shared/robots/op3_reference.txt (or $HRP_ROBOT_REFERENCE), Config/robots/op3/robot.lua,
Config/robots/op3/op3.urdf.

Conventions of the generated file (what the sim DCM and the kinematics rely on):
- Every link frame sits at its joint's anchor and is parallel to the world frame at the zero pose
  (all joints 0), so joint origins are pure translations and each joint axis is the reference's
  world-frame axis. body_link's frame is the midpoint of the two hip-yaw anchors.
- Inertials: mass, COM and the inertia tensor about the COM, world-aligned, as in the reference.
- Collision (and visual) boxes: the reference's oriented boxes, rotation converted to URDF rpy.
- Joint limits come from Config/robots/op3/robot.lua (the single source of limits); effort and velocity
  are the XM430-W350's (stall torque as specified for the platform, no-load speed at 12 V);
  dynamics damping/friction are the reference's servo model.
- The head camera is a fixed link `camera_link` on head_tilt_link: x along the optical axis,
  z image-up; its field of view lives in Config/robots/op3/camera.lua.
"""
import math
import os
import re
import sys

EFFORT = 5.0           # N*m, servo torque limit at hardness 1
VELOCITY = 4.82        # rad/s, XM430-W350 no-load speed at 12 V (46 rpm)
DAMPING = 1.084        # N*m*s/rad (reference servo model)
FRICTION = 0.03        # N*m (reference servo model)


def fail(msg):
    sys.stderr.write('gen_urdf: ' + msg + '\n')
    sys.exit(1)


def read_reference(path):
    try:
        lines = open(path).read().splitlines()
    except OSError as e:
        fail('%s: %s' % (path, e))
    bodies, boxes, camera = [], [], None
    section = None
    for n, raw in enumerate(lines, 1):
        line = raw.split('#', 1)[0].strip()
        if not line:
            continue
        if line in ('BODIES', 'COLLISION', 'CAMERA'):
            section = line
            continue
        f = line.split()
        where = '%s:%d' % (path, n)
        try:
            if section == 'BODIES':
                if len(f) != 19:
                    fail('%s: body line needs 19 fields, has %d' % (where, len(f)))
                bodies.append(dict(name=f[0], parent=f[1], mass=float(f[2]),
                                   com=[float(x) for x in f[3:6]],
                                   inertia=[float(x) for x in f[6:12]],
                                   joint=f[12], axis=[float(x) for x in f[13:16]],
                                   anchor=[float(x) for x in f[16:19]]))
            elif section == 'COLLISION':
                if len(f) != 17:
                    fail('%s: collision line needs 17 fields, has %d' % (where, len(f)))
                boxes.append(dict(body=f[0], kind=f[1], center=[float(x) for x in f[2:5]],
                                  size=[float(x) for x in f[5:8]],
                                  R=[float(x) for x in f[8:17]]))
            elif section == 'CAMERA':
                if len(f) != 6 or f[4] != 'fovy_deg':
                    fail('%s: camera line must be "link x y z fovy_deg DEG"' % where)
                camera = dict(body=f[0], pos=[float(x) for x in f[1:4]], fovy=float(f[5]))
            else:
                fail('%s: data before any section' % where)
        except ValueError as e:
            fail('%s: %s' % (where, e))
    if not bodies:
        fail('%s: no BODIES' % path)
    if camera is None:
        fail('%s: no CAMERA' % path)
    return bodies, boxes, camera


def read_limits(path):
    try:
        text = open(path).read()
    except OSError as e:
        fail('%s: %s' % (path, e))
    m = re.search(r'limits\s*=\s*\{(.*?)\n\s*\},', text, re.S)
    if not m:
        fail('%s: no limits table' % path)
    lim = {}
    for name, lo, hi in re.findall(r'(\w+)\s*=\s*\{\s*([-+0-9.eE]+)\s*,\s*([-+0-9.eE]+)\s*\}',
                                   m.group(1)):
        lim[name] = (float(lo), float(hi))
    return lim


def orthonormalize(R):
    """Nearest rotation (Gram-Schmidt on the columns; boxes from mesh fits are near-orthonormal)."""
    c = [[R[0], R[3], R[6]], [R[1], R[4], R[7]], [R[2], R[5], R[8]]]

    def norm(v):
        n = math.sqrt(sum(x * x for x in v))
        return [x / n for x in v]

    def dot(a, b):
        return sum(x * y for x, y in zip(a, b))

    x = norm(c[0])
    y = norm([a - dot(c[1], x) * b for a, b in zip(c[1], x)])
    z = [x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2], x[0] * y[1] - x[1] * y[0]]
    if dot(z, c[2]) < 0:
        fail('collision box rotation is a reflection')
    return [[x[0], y[0], z[0]], [x[1], y[1], z[1]], [x[2], y[2], z[2]]]


def rpy(R):
    """URDF rpy (R = Rz(yaw) Ry(pitch) Rx(roll)) of a row-major 3x3 rotation (world = R * local)."""
    M = orthonormalize(R)
    pitch = math.atan2(-M[2][0], math.hypot(M[0][0], M[1][0]))
    if abs(math.cos(pitch)) > 1e-9:
        roll = math.atan2(M[2][1], M[2][2])
        yaw = math.atan2(M[1][0], M[0][0])
    else:
        roll = 0.0
        yaw = math.atan2(-M[0][1], M[1][1])
    return roll, pitch, yaw


def fmt(v):
    return ' '.join('%.9g' % (0.0 if abs(x) < 1e-15 else x) for x in v)


def main():
    root = os.path.abspath(os.path.join(os.path.dirname(__file__), '..', '..'))
    ref = sys.argv[1] if len(sys.argv) > 1 else os.environ.get(
        'HRP_ROBOT_REFERENCE', '/work/shared/robots/op3_reference.txt')
    robot_lua = sys.argv[2] if len(sys.argv) > 2 else os.path.join(root, 'Config/robots/op3/robot.lua')
    out = sys.argv[3] if len(sys.argv) > 3 else os.path.join(root, 'Config/robots/op3/op3.urdf')
    bodies, boxes, camera = read_reference(ref)
    limits = read_limits(robot_lua)

    origin = {}   # link frame origin in the world at the zero pose
    for b in bodies:
        if b['joint'] == 'floating':
            hips = [c['anchor'] for c in bodies if c['joint'].endswith('hip_yaw')]
            if len(hips) != 2:
                fail('need two *_hip_yaw joints to place body_link')
            origin[b['name']] = [(hips[0][i] + hips[1][i]) / 2 for i in range(3)]
        else:
            origin[b['name']] = b['anchor']
    names = set(origin)

    out_lines = []
    w = out_lines.append
    w('<?xml version="1.0"?>')
    w('<!-- Generated by Platforms/Sim/gen_urdf.py from %s and %s. Do not edit;'
      % (os.path.basename(ref), os.path.relpath(robot_lua, root)))
    w('     rerun the script. Link frames: at the joint anchor, world-aligned at the zero pose. -->')
    w('<robot name="op3">')
    for b in bodies:
        o = origin[b['name']]
        com = [b['com'][i] - o[i] for i in range(3)]
        ixx, iyy, izz, ixy, ixz, iyz = b['inertia']
        w('  <link name="%s">' % b['name'])
        w('    <inertial>')
        w('      <origin xyz="%s" rpy="0 0 0"/>' % fmt(com))
        w('      <mass value="%.9g"/>' % b['mass'])
        w('      <inertia ixx="%.9g" ixy="%.9g" ixz="%.9g" iyy="%.9g" iyz="%.9g" izz="%.9g"/>'
          % (ixx, ixy, ixz, iyy, iyz, izz))
        w('    </inertial>')
        for k, box in enumerate(c for c in boxes if c['body'] == b['name']):
            c = [box['center'][i] - o[i] for i in range(3)]
            r = rpy(box['R'])
            for tag in ('visual', 'collision'):
                w('    <%s name="%s_%s%d">' % (tag, box['kind'], b['name'], k))
                w('      <origin xyz="%s" rpy="%s"/>' % (fmt(c), fmt(r)))
                w('      <geometry><box size="%s"/></geometry>' % fmt(box['size']))
                w('    </%s>' % tag)
        w('  </link>')
        if b['joint'] == 'floating':
            continue
        if b['parent'] not in names:
            fail('%s: parent %s unknown' % (b['name'], b['parent']))
        if b['joint'] not in limits:
            fail('%s: joint %s has no limits in %s' % (b['name'], b['joint'], robot_lua))
        po = origin[b['parent']]
        lo, hi = limits[b['joint']]
        w('  <joint name="%s" type="revolute">' % b['joint'])
        w('    <parent link="%s"/>' % b['parent'])
        w('    <child link="%s"/>' % b['name'])
        w('    <origin xyz="%s" rpy="0 0 0"/>' % fmt([o[i] - po[i] for i in range(3)]))
        w('    <axis xyz="%s"/>' % fmt(b['axis']))
        w('    <limit lower="%.9g" upper="%.9g" effort="%.9g" velocity="%.9g"/>'
          % (lo, hi, EFFORT, VELOCITY))
        w('    <dynamics damping="%.9g" friction="%.9g"/>' % (DAMPING, FRICTION))
        w('  </joint>')
    if camera['body'] not in names:
        fail('camera on unknown link %s' % camera['body'])
    co = origin[camera['body']]
    w('  <!-- head camera: x along the optical axis, z image-up; vertical fov %.4g deg (Config/robots/op3/camera.lua) -->'
      % camera['fovy'])
    w('  <link name="camera_link"/>')
    w('  <joint name="camera_joint" type="fixed">')
    w('    <parent link="%s"/>' % camera['body'])
    w('    <child link="camera_link"/>')
    w('    <origin xyz="%s" rpy="0 0 0"/>' % fmt([camera['pos'][i] - co[i] for i in range(3)]))
    w('  </joint>')
    w('</robot>')
    with open(out, 'w') as f:
        f.write('\n'.join(out_lines) + '\n')
    print('gen_urdf: wrote %s (%d links, %d boxes)' % (out, len(bodies) + 1, len(boxes)))


if __name__ == '__main__':
    main()
