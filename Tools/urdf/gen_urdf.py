#!/usr/bin/env python3
"""Writes a robot's description (URDF) from reference data plus the robot's own data.

    Tools/urdf/gen_urdf.py ROBOT REFERENCE [--out FILE]

ROBOT names Config/robots/<ROBOT>; REFERENCE is a reference file in the shared format (e.g.
../shared/robots/darwin_reference.txt: sections BODIES, COLLISION, optional CAMERA; sections this
tool does not use, such as LIMITS, ACTUATORS or SENSORS, are skipped). The output is the file that
robot.lua's `description` names, beside robot.lua (or FILE); it is committed. A developer runs this
by hand: nothing at run time reads the reference.

What comes from where:
- BODIES: links, inertials (mass, COM, inertia about the COM, world-aligned), joints (parent, axis).
- COLLISION: collision (and visual) boxes; kinds named sole* are the foot contact boxes.
- robot.lua (read through Lib/Config.lua, all layers, exported by LuaJIT):
  joints (every reference joint must be listed, and nothing else), limits (rad), actuator (the
  model of each joint, Config/common/actuators.lua: torque -> <limit effort>, speed -> velocity,
  damping/friction -> <dynamics>), chains (the torso frame's origin is the midpoint of the two
  legs' first joint anchors), frames (massless fixed frames: camera_link, l_sole, l_hand ...,
  each { link = parent link, xyz = zero-pose origin, rpy = zero-pose orientation }, in the reference
  frame; camera_link without xyz takes the reference's CAMERA point), collision_skip (optional:
  COLLISION kinds left out, e.g. a reference's alternative sole set), added_masses (optional: mass
  the reference lacks, each { link, mass, com = xyz, size = xyz of a uniform box about com }, merged
  into the link's inertial by the parallel-axis rule; robot.lua says where the mass comes from).

Conventions of the generated file (what the sim and the kinematics rely on):
- Every link frame sits at its joint's anchor and is parallel to the world frame at the zero pose
  (all joints 0), so joint origins are pure translations and each joint axis is the reference's
  world-frame axis. The root link's frame: see chains above.
- Rerunning with the same inputs writes the same bytes.
"""
import json
import math
import os
import re
import subprocess
import sys

SECTIONS_USED = ('BODIES', 'COLLISION', 'CAMERA')

# Exports robot.lua and the actuator models as JSON through the one config reader.
LUA_EXPORT = r'''
local root, robot = ...
package.path = root .. '/Lib/?.lua;' .. package.path
local Config = require('Config')
local function enc(v)
  local t = type(v)
  if t == 'number' then return string.format('%.17g', v)
  elseif t == 'string' then return (string.format('%q', v))
  elseif t == 'boolean' then return tostring(v)
  elseif t == 'table' then
    local parts = {}
    if rawget(v, 1) ~= nil then
      for _, x in ipairs(v) do parts[#parts + 1] = enc(x) end
      return '[' .. table.concat(parts, ',') .. ']'
    end
    local keys = {}
    for k in pairs(v) do keys[#keys + 1] = k end
    table.sort(keys, function(x, y) return tostring(x) < tostring(y) end)
    for _, k in ipairs(keys) do parts[#parts + 1] = enc(tostring(k)) .. ':' .. enc(v[k]) end
    return '{' .. table.concat(parts, ',') .. '}'
  end
  error('cannot export a ' .. t)
end
local r, rfiles = Config.export('robot', { robot = robot })
local a, afiles = Config.export('actuators', { robot = robot })
io.write(enc({ robot = r, robot_files = rfiles, actuators = a, actuator_files = afiles }))
'''


def fail(msg):
    sys.stderr.write('gen_urdf: ' + msg + '\n')
    sys.exit(1)


def read_reference(path):
    try:
        lines = open(path).read().splitlines()
    except OSError as e:
        fail('%s: %s' % (path, e))
    bodies, boxes, camera, skipped = [], [], None, []
    section = None
    for n, raw in enumerate(lines, 1):
        line = raw.split('#', 1)[0].strip()
        if not line:
            continue
        if re.fullmatch(r'[A-Z][A-Z0-9_]*', line):
            section = line
            if section not in SECTIONS_USED:
                skipped.append(section)
            continue
        f = line.split()
        where = '%s:%d' % (path, n)
        if section is None:
            fail('%s: data before any section' % where)
        if section not in SECTIONS_USED:
            continue
        try:
            if section == 'BODIES':
                if len(f) != 19:
                    fail('%s: body line needs 19 fields, has %d' % (where, len(f)))
                bodies.append(dict(name=f[0], parent=f[1], mass=float(f[2]),
                                   com=[float(x) for x in f[3:6]],
                                   inertia=[float(x) for x in f[6:12]],
                                   joint=f[12], axis=[float(x) for x in f[13:16]],
                                   anchor=[float(x) for x in f[16:19]], where=where))
            elif section == 'COLLISION':
                if len(f) != 17:
                    fail('%s: collision line needs 17 fields, has %d' % (where, len(f)))
                boxes.append(dict(body=f[0], kind=f[1], center=[float(x) for x in f[2:5]],
                                  size=[float(x) for x in f[5:8]],
                                  R=[float(x) for x in f[8:17]], where=where))
            else:
                if len(f) != 6 or f[4] != 'fovy_deg':
                    fail('%s: camera line must be "link x y z fovy_deg DEG"' % where)
                camera = dict(body=f[0], pos=[float(x) for x in f[1:4]], fovy=float(f[5]))
        except ValueError as e:
            fail('%s: %s' % (where, e))
    if not bodies:
        fail('%s: no BODIES' % path)
    return bodies, boxes, camera, skipped


def read_robot(root, robot):
    try:
        res = subprocess.run(['luajit', '-', root, robot], input=LUA_EXPORT, capture_output=True,
                             text=True, check=False)
    except OSError as e:
        fail('luajit: %s' % e)
    if res.returncode != 0:
        fail('reading the config of robot %s: %s' % (robot, res.stderr.strip()))
    return json.loads(res.stdout)


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


def vec3(v, what):
    if not isinstance(v, list) or len(v) != 3 or not all(isinstance(x, (int, float)) for x in v):
        fail('%s must be a list of 3 numbers' % what)
    return [float(x) for x in v]


def add_mass(body, mass, com, size):
    """Merges a uniform box (mass, centre com, world-aligned edges size) into a body's inertial."""
    m0, c0 = body['mass'], body['com']
    m = m0 + mass
    c = [(m0 * c0[i] + mass * com[i]) / m for i in range(3)]
    # tensors about the new COM: each part's own tensor plus its shift (I + m (|d|^2 E - d d^T))
    def shifted(I, mm, p):
        d = [p[i] - c[i] for i in range(3)]
        dd = sum(x * x for x in d)
        ixx, iyy, izz, ixy, ixz, iyz = I
        return [ixx + mm * (dd - d[0] * d[0]), iyy + mm * (dd - d[1] * d[1]), izz + mm * (dd - d[2] * d[2]),
                ixy - mm * d[0] * d[1], ixz - mm * d[0] * d[2], iyz - mm * d[1] * d[2]]
    sx, sy, sz = size
    box = [mass * (sy * sy + sz * sz) / 12, mass * (sx * sx + sz * sz) / 12, mass * (sx * sx + sy * sy) / 12,
           0.0, 0.0, 0.0]
    a, b = shifted(body['inertia'], m0, c0), shifted(box, mass, com)
    body['mass'], body['com'], body['inertia'] = m, c, [a[i] + b[i] for i in range(6)]


def apply_robot_data(robot, rfiles, bodies, boxes):
    """robot.lua's collision_skip and added_masses applied to the reference's bodies and boxes."""
    skip = robot.get('collision_skip') or []
    if not isinstance(skip, list) or not all(isinstance(k, str) for k in skip):
        fail('%s: collision_skip must be a list of COLLISION kinds' % rfiles)
    for k in skip:
        if not any(b['kind'] == k for b in boxes):
            fail("%s: collision_skip names kind '%s', which no COLLISION line has" % (rfiles, k))
    boxes[:] = [b for b in boxes if b['kind'] not in skip]
    by_name = {b['name']: b for b in bodies}
    added = robot.get('added_masses') or []
    if not isinstance(added, list):
        fail('%s: added_masses must be a list of { link, mass, com, size }' % rfiles)
    for n, a in enumerate(added, 1):
        what = '%s: added_masses[%d]' % (rfiles, n)
        if not isinstance(a, dict) or a.get('link') not in by_name:
            fail("%s: link '%s' is not a body of the reference" % (what, a.get('link') if isinstance(a, dict) else a))
        if not isinstance(a.get('mass'), (int, float)) or not a['mass'] > 0:
            fail('%s: mass must be a number > 0' % what)
        add_mass(by_name[a['link']], float(a['mass']), vec3(a.get('com'), what + '.com'),
                 vec3(a.get('size'), what + '.size'))


def chain_joints(robot, name, files):
    chains = robot.get('chains') or {}
    c = chains.get(name)
    if c is None:
        return None
    joints = c.get('joints') or (robot.get('groups') or {}).get(name)
    if not joints:
        fail('%s: chains.%s has no joints (and groups.%s is missing)' % (files, name, name))
    return joints


def main():
    args = sys.argv[1:]
    out = None
    if len(args) == 4 and args[2] == '--out':
        out = args[3]
        args = args[:2]
    if len(args) != 2:
        sys.stderr.write(__doc__)
        sys.exit(2)
    robot_name, ref = args
    root = os.path.abspath(os.path.join(os.path.dirname(__file__), '..', '..'))
    bodies, boxes, camera, skipped = read_reference(ref)
    for s in skipped:
        print('gen_urdf: %s: section %s not used (skipped)' % (os.path.basename(ref), s))
    data = read_robot(root, robot_name)
    robot, models = data['robot'], data['actuators']
    rfiles, afiles = data['robot_files'], data['actuator_files']
    apply_robot_data(robot, rfiles, bodies, boxes)
    if not isinstance(robot.get('description'), str):
        fail("%s: key 'description' (the URDF's file name) missing" % rfiles)
    out = out or os.path.join(root, 'Config', 'robots', robot_name, robot['description'])

    # joints: the reference's and the robot's joint list must be the same set
    ref_joints = [b['joint'] for b in bodies if b['joint'] != 'floating']
    listed = robot.get('joints') or []
    for j in ref_joints:
        if j not in listed:
            fail("%s: joint '%s' of %s is not in joints" % (rfiles, j, os.path.basename(ref)))
    for j in listed:
        if j not in ref_joints:
            fail("%s: joints lists '%s', which %s does not have" % (rfiles, j, os.path.basename(ref)))
    limits, actuator = robot.get('limits') or {}, robot.get('actuator') or {}
    for j in ref_joints:
        lim = limits.get(j)
        if not isinstance(lim, list) or len(lim) != 2 or not lim[0] < lim[1]:
            fail("%s: limits.%s must be { min, max } with min < max" % (rfiles, j))
        model = actuator.get(j)
        if model not in models:
            fail("%s: actuator.%s is '%s', not a model of %s" % (rfiles, j, model, afiles))
        for k in ('torque', 'speed', 'damping', 'friction'):
            if not isinstance(models[model].get(k), (int, float)):
                fail("%s: model '%s' has no number '%s'" % (afiles, model, k))

    # link frame origins (world, zero pose): at the joint anchor; the root between the legs
    origin = {}
    by_joint = {b['joint']: b for b in bodies}
    for b in bodies:
        if b['joint'] != 'floating':
            origin[b['name']] = b['anchor']
    roots = [b for b in bodies if b['joint'] == 'floating']
    if len(roots) != 1:
        fail('%s: needs exactly one floating (root) body, has %d' % (ref, len(roots)))
    legs = [chain_joints(robot, s, rfiles) for s in ('lleg', 'rleg')]
    if legs[0] and legs[1] and legs[0][0] in by_joint and legs[1][0] in by_joint:
        a, b = by_joint[legs[0][0]]['anchor'], by_joint[legs[1][0]]['anchor']
        origin[roots[0]['name']] = [(a[i] + b[i]) / 2 for i in range(3)]
    else:
        origin[roots[0]['name']] = [0.0, 0.0, 0.0]
    names = set(origin)

    # frames: massless fixed links
    frames = []
    for fname, f in sorted((robot.get('frames') or {}).items()):
        what = '%s: frames.%s' % (rfiles, fname)
        link = f.get('link')
        if link not in names:
            fail("%s: link '%s' is not a body of %s" % (what, link, os.path.basename(ref)))
        if fname in names:
            fail('%s: the name is a body already' % what)
        xyz = f.get('xyz')
        if xyz is None:
            if fname != 'camera_link' or camera is None:
                fail('%s: needs xyz (only camera_link may take the reference\'s CAMERA point)' % what)
            if camera['body'] != link:
                fail("%s: link '%s', but the reference's CAMERA is on '%s'" % (what, link, camera['body']))
            xyz = camera['pos']
        xyz = vec3(xyz, what + '.xyz')
        r = vec3(f.get('rpy', [0, 0, 0]), what + '.rpy')
        frames.append(dict(name=fname, link=link, xyz=xyz, rpy=r))

    lines = []
    w = lines.append
    w('<?xml version="1.0"?>')
    w('<!-- Generated by Tools/urdf/gen_urdf.py from %s, %s and %s. Do not edit;'
      % (os.path.basename(ref), rfiles, afiles))
    w('     rerun the script. Link frames: at the joint anchor, world-aligned at the zero pose. -->')
    w('<robot name="%s">' % robot_name)
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
            fail('%s: %s: parent %s unknown' % (b['where'], b['name'], b['parent']))
        po = origin[b['parent']]
        lo, hi = limits[b['joint']]
        model_name = actuator[b['joint']]
        model = models[model_name]
        w('  <joint name="%s" type="revolute">' % b['joint'])
        w('    <parent link="%s"/>' % b['parent'])
        w('    <child link="%s"/>' % b['name'])
        w('    <origin xyz="%s" rpy="0 0 0"/>' % fmt([o[i] - po[i] for i in range(3)]))
        w('    <axis xyz="%s"/>' % fmt(b['axis']))
        w('    <!-- actuator %s -->' % model_name)
        w('    <limit lower="%.9g" upper="%.9g" effort="%.9g" velocity="%.9g"/>'
          % (lo, hi, model['torque'], model['speed']))
        w('    <dynamics damping="%.9g" friction="%.9g"/>' % (model['damping'], model['friction']))
        w('  </joint>')
    for f in frames:
        lo_ = origin[f['link']]
        if f['name'] == 'camera_link':
            fov = ('; vertical fov %.4g deg in the reference (camera.lua holds it)' % camera['fovy']
                   if camera else '')
            w('  <!-- head camera: x along the optical axis, z image-up%s -->' % fov)
        w('  <link name="%s"/>' % f['name'])
        w('  <joint name="%s_joint" type="fixed">' % f['name'])
        w('    <parent link="%s"/>' % f['link'])
        w('    <child link="%s"/>' % f['name'])
        w('    <origin xyz="%s" rpy="%s"/>' % (fmt([f['xyz'][i] - lo_[i] for i in range(3)]), fmt(f['rpy'])))
        w('  </joint>')
    w('</robot>')
    with open(out, 'w') as fh:
        fh.write('\n'.join(lines) + '\n')
    print('gen_urdf: wrote %s (%d links, %d boxes, %d frames)' % (out, len(bodies), len(boxes), len(frames)))


if __name__ == '__main__':
    main()
