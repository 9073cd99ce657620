-- luacheck: std +busted
-- Kinematics of the real bodies (Config/robots/op3, Config/robots/darwin) through the Lua API:
-- FK(IK(x)) = x over the workspace, known poses,
-- unreachable and NaN targets, the OP3's COM against the reference, agreement with the URDF.
local kin = require('kinematics')
local native = require('native')

local sin, cos, abs, sqrt = math.sin, math.cos, math.abs, math.sqrt

-- Deterministic pseudo-random numbers (LCG) so a failure can be replayed.
local function rng(seed)
  local s = seed
  return function(lo, hi)
    s = (s * 1103515245 + 12345) % 2147483648
    return lo + (hi - lo) * s / 2147483648
  end
end

local function matmul(A, B)
  local C = {}
  for i = 0, 2 do
    for j = 0, 2 do
      local v = 0
      for k = 0, 2 do v = v + A[3 * i + k + 1] * B[3 * k + j + 1] end
      C[3 * i + j + 1] = v
    end
  end
  return C
end

local function rpy_rot(r, p, y)
  local Rx = { 1, 0, 0, 0, cos(r), -sin(r), 0, sin(r), cos(r) }
  local Ry = { cos(p), 0, sin(p), 0, 1, 0, -sin(p), 0, cos(p) }
  local Rz = { cos(y), -sin(y), 0, sin(y), cos(y), 0, 0, 0, 1 }
  return matmul(Rz, matmul(Ry, Rx))
end

-- Angle between two rotations (row-major 3x3), robust near zero.
local function rot_dist(A, B)
  local M = matmul({ A[1], A[4], A[7], A[2], A[5], A[8], A[3], A[6], A[9] }, B)
  local s = sqrt((M[8] - M[6]) ^ 2 + (M[3] - M[7]) ^ 2 + (M[4] - M[2]) ^ 2) / 2
  local c = (M[1] + M[5] + M[9] - 1) / 2
  return math.atan2(s, c)
end

local function finite(v) return v == v and v ~= math.huge and v ~= -math.huge end

local function pose_error(p1, p2)
  local dp = sqrt((p1[1] - p2[1]) ^ 2 + (p1[2] - p2[2]) ^ 2 + (p1[3] - p2[3]) ^ 2)
  return dp, rot_dist(rpy_rot(p1[4], p1[5], p1[6]), rpy_rot(p2[4], p2[5], p2[6]))
end

for _, robot in ipairs({ 'op3', 'darwin' }) do
  describe('kinematics of ' .. robot, function()
    local m = kin.load({ robot = robot })
    local leg_len = -m:leg_fk('l', { 0, 0, 0, 0, 0, 0 })[3] -- torso origin to sole, zero pose

    it('FK(IK(x)) = x over sampled foot poses of the walking workspace', function()
      local R = rng(42)
      local worst_p, worst_r, n, flagged = 0, 0, 0, 0
      local q, p2 = {}, {}
      for _, side in ipairs({ 'l', 'r' }) do
        local sy = side == 'l' and 1 or -1
        local y0 = m:leg_fk(side, { 0, 0, 0, 0, 0, 0 })[2]
        for _ = 1, 3000 do
          local pose = { R(-0.09, 0.09), y0 + sy * R(-0.03, 0.06), -leg_len + R(0.02, 0.08),
            R(-0.3, 0.3), R(-0.3, 0.3), R(-0.6, 0.6) }
          local _, flags = m:leg_ik(side, pose, q)
          if flags == 0 then
            m:leg_fk(side, q, p2)
            local dp, dr = pose_error(pose, p2)
            worst_p, worst_r, n = math.max(worst_p, dp), math.max(worst_r, dr), n + 1
          else
            flagged = flagged + 1
          end
        end
      end
      print(string.format('# %s: %d poses solved exactly (%d flagged), worst %.3g m, %.3g rad',
        robot, n, flagged, worst_p, worst_r))
      assert.is_true(n > 5400) -- nearly all of this box is reachable within the limits
      assert.is_true(worst_p < 1e-6)
      assert.is_true(worst_r < 1e-6)
    end)

    it('FK(IK(FK(q))) = FK(q) for random joint angles', function()
      local R = rng(7)
      local q, qs, p1, p2 = {}, {}, {}, {}
      local worst_p, worst_r = 0, 0
      for _, side in ipairs({ 'l', 'r' }) do
        local ks = side == 'l' and 1 or -1 -- knee bend sign from the axes (OP3 and DARwIn: l +y, r -y)
        for _ = 1, 2000 do
          -- the solver's branch: knee bent backward, |ankle roll| < pi/2, foot pitched less than 90 deg
          repeat
            q[1], q[2], q[3] = R(-0.5, 0.5), R(-0.4, 0.4), R(-1.0, 0.6)
            q[4], q[5], q[6] = ks * R(0.02, 2.0), R(-1.0, 1.0), R(-0.4, 0.4)
          until abs(q[3] + q[4] - q[5]) < 1.4
          m:leg_fk(side, q, p1)
          local _, flags = m:leg_ik(side, p1, qs)
          assert.are.equal(0, flags)
          m:leg_fk(side, qs, p2)
          local dp, dr = pose_error(p1, p2)
          worst_p, worst_r = math.max(worst_p, dp), math.max(worst_r, dr)
        end
      end
      assert.is_true(worst_p < 1e-6 and worst_r < 1e-6, string.format('%.3g m %.3g rad', worst_p, worst_r))
    end)

    it('zero pose: the foot stands straight below the hip and IK gives straight legs', function()
      for _, side in ipairs({ 'l', 'r' }) do
        local p = m:leg_fk(side, { 0, 0, 0, 0, 0, 0 })
        -- soles on z = 0 of the reference frame: the foot is origin.z below the torso origin
        assert.is_true(abs(p[3] + m.origin[3]) < 1e-12)
        local q, flags = m:leg_ik(side, p)
        assert.are.equal(0, flags)
        for k = 1, 6 do assert.is_true(abs(q[k]) < 1e-6, 'joint ' .. k .. ': ' .. q[k]) end
      end
    end)

    it('stays exact while the knee nears straight and fully folded', function()
      for _, dz in ipairs({ 1e-9, 1e-6, 1e-3 }) do
        local p = m:leg_fk('l', { 0, 0, 0, 0, 0, 0 })
        p[3] = p[3] + dz
        local q, flags = m:leg_ik('l', p)
        assert.are.equal(0, flags)
        local dp = pose_error(p, m:leg_fk('l', q))
        assert.is_true(dp < 1e-6)
      end
    end)

    it('too far: nearest reachable solution and the flag; NaN/inf: finite and flagged', function()
      local p0 = m:leg_fk('l', { 0, 0, 0, 0, 0, 0 })
      local x0, y0 = p0[1], p0[2]
      local q, flags = m:leg_ik('l', x0, y0, -1.0, 0, 0, 0)
      assert.are.equal(kin.UNREACHABLE, flags)
      local p = m:leg_fk('l', q)
      assert.is_true(abs(p[3] + leg_len) < 1e-6) -- leg straight, pointing at the target
      for k = 1, 6 do assert.is_true(abs(q[k]) < 1e-6) end
      local nan, inf = 0 / 0, math.huge
      local z = -leg_len + 0.03
      for _, bad in ipairs({ { nan, y0, z, 0, 0, 0 }, { x0, inf, z, 0, 0, 0 }, { x0, y0, z, nan, -inf, nan },
        { nan, nan, nan, nan, nan, nan }, { 1e308, -1e308, 1e308, 0, 0, 0 } }) do
        local qb, fb = m:leg_ik('l', bad)
        assert.is_true(fb > 0)
        for k = 1, 6 do assert.is_true(finite(qb[k])) end
      end
      local _, fn = m:leg_ik('l', nan, y0, -leg_len + 0.03, 0, 0, 0)
      assert.are.equal(kin.BAD_INPUT, fn)
    end)

    it('joint limits: a target beyond them is clamped and flagged', function()
      local y0 = m:leg_fk('l', { 0, 0, 0, 0, 0, 0 })[2]
      local q, flags = m:leg_ik('l', 0, y0, -leg_len + 0.05, 0, 0, 2.0) -- hip yaw 2 rad, limit 1.2
      -- both bodies limit hip yaw to +-1.2 rad (Config/robots/<robot>/robot.lua)
      assert.are.equal(kin.JOINT_LIMIT, flags)
      assert.is_true(abs(q[1]) <= 1.2 + 1e-12)
    end)

    it('look_at points the optical axis at the target', function()
      local R = rng(3)
      for _ = 1, 200 do
        local t = { R(0.3, 4), R(-1.5, 1.5), R(-0.5, -0.1) - m.origin[3] }
        local qh, flags = m:look_at(t)
        if flags == 0 then
          local c = m:head_fk(qh)
          local d = { t[1] - c[1], t[2] - c[2], t[3] - c[3] }
          local nd = sqrt(d[1] ^ 2 + d[2] ^ 2 + d[3] ^ 2)
          local cosang = (d[1] * c.R[1] + d[2] * c.R[4] + d[3] * c.R[7]) / nd
          assert.is_true(cosang > 1 - 1e-10)
        end
      end
    end)

    it('camera pose: height above the sole, tilts with the torso', function()
      local q = {}
      for i = 1, m.n do q[i] = 0 end
      local cam = m:camera_pose(q, { 0, 0, 0 })
      local c0 = m:head_fk({ 0, 0 })
      assert.is_true(abs(cam.height - (c0[3] + m.origin[3])) < 1e-12)
      local cp = m:camera_pose(q, { 0, 0.2, 0 }) -- torso pitched forward: the camera moves forward, down
      assert.is_true(abs(cp[1] - (cos(0.2) * c0[1] + sin(0.2) * c0[3])) < 1e-12)
      assert.is_true(abs(cp[3] - (-sin(0.2) * c0[1] + cos(0.2) * c0[3])) < 1e-12)
    end)

    it('legs_ik fills both legs into a whole-body array without garbage', function()
      local q = {}
      for i = 1, m.n do q[i] = 0 end
      local lp = { 0.01, m:leg_fk('l', { 0, 0, 0, 0, 0, 0 })[2], -leg_len + 0.04, 0, 0, 0.1 }
      local rp = { -0.01, m:leg_fk('r', { 0, 0, 0, 0, 0, 0 })[2], -leg_len + 0.04, 0, 0, -0.1 }
      assert.are.equal(0, m:legs_ik(lp, rp, q))
      local ql = {}
      for k = 1, 6 do ql[k] = q[m.leg_index[0][k]] end
      assert.is_true(pose_error(lp, m:leg_fk('l', ql)) < 1e-9)
      local out = {}
      local function run(n)
        for i = 1, n do
          lp[1] = 0.0001 * (i % 100)
          m:legs_ik(lp, rp, q)
          m:leg_ik('r', rp, out)
        end
      end
      run(20000) -- let the JIT compile first: trace recording allocates
      collectgarbage('collect')
      collectgarbage('stop')
      local before = collectgarbage('count')
      run(20000)
      local grown = collectgarbage('count') - before
      collectgarbage('restart')
      assert.is_true(grown < 1, string.format('%.1f KiB allocated', grown))
    end)

    it('refuses a wrong side and a wrong model', function()
      assert.has_error(function() m:leg_ik('x', 0, 0, 0, 0, 0, 0) end)
      assert.has_error(function() kin.leg_ik({}, 'l', 0, 0, 0, 0, 0, 0) end)
    end)
  end)
end

describe('OP3 model against the reference data', function()
  local m = kin.load({ robot = 'op3' })
  local q0 = {}
  for i = 1, m.n do q0[i] = 0 end

  it('whole-body COM at the zero pose is the reference COM', function()
    local c = m:com(q0)
    local ref = { -0.0105675, 7.17532e-05, 0.274312 } -- op3_reference.txt, reference frame
    for k = 1, 3 do
      assert.is_true(abs(c[k] + m.origin[k] - ref[k]) < 1e-6, k .. ': ' .. (c[k] + m.origin[k]))
    end
    assert.is_true(abs(m.mass - 3.1475) < 1e-4)
  end)

  it('a bent-knee pose matches the hand computation', function()
    -- left: hip pitch (+y) -0.4 swings the thigh forward, knee (+y) 0.8, ankle pitch (-y) 0.4 keeps
    -- the foot flat. Hip centre (0.0001, 0.035, 0.25065), knee axis 0.11015 lower, ankle 0.11 more.
    local p = m:leg_fk('l', { 0, 0, -0.4, 0.8, 0.4, 0 })
    local ax = 0.0001 + 0.11015 * sin(0.4) - 0.11 * sin(0.4)
    local az = 0.25065 - (0.11015 + 0.11) * cos(0.4)
    local want = { ax, 0.035, az - 0.0305 - m.origin[3] }
    for k = 1, 3 do assert.is_true(abs(p[k] - want[k]) < 1e-12, k .. ': ' .. p[k] .. ' vs ' .. want[k]) end
    for k = 4, 6 do assert.is_true(abs(p[k]) < 1e-12) end
    -- right leg: mirrored axes, so mirrored signs give the mirrored pose
    local pr = m:leg_fk('r', { 0, 0, 0.4, -0.8, -0.4, 0 })
    assert.is_true(abs(pr[1] - want[1]) < 1e-12 and abs(pr[2] + want[2]) < 1e-12)
    assert.is_true(abs(pr[3] - want[3]) < 1e-12)
    local q = m:leg_ik('l', p)
    local expect = { 0, 0, -0.4, 0.8, 0.4, 0 }
    for k = 1, 6 do assert.is_true(abs(q[k] - expect[k]) < 1e-9) end
  end)
end)

-- A tiny URDF reader: joints (parent/child link, origin, axis) and link masses/COMs.
local function read_urdf(path)
  local f = assert(io.open(path, 'r'))
  local text = f:read('*a')
  f:close()
  local function nums(s)
    local t = {}
    for v in (s or ''):gmatch('[^%s]+') do t[#t + 1] = tonumber(v) end
    return t
  end
  local links, joints = {}, {}
  for name, body in text:gmatch('<link%s+name="([^"]+)"%s*>(.-)</link>') do
    local inertial = body:match('<inertial>(.-)</inertial>')
    if inertial then
      links[name] = {
        mass = tonumber(inertial:match('<mass%s+value="([^"]+)"')),
        com = nums(inertial:match('<origin[^>]-xyz="([^"]+)"')),
      }
    end
  end
  for name, body in text:gmatch('<joint%s+name="([^"]+)"[^>]*>(.-)</joint>') do
    local origin = body:match('<origin[^>]*>') or ''
    joints[name] = {
      parent = body:match('<parent%s+link="([^"]+)"'),
      child = body:match('<child%s+link="([^"]+)"'),
      xyz = nums(origin:match('xyz="([^"]+)"')),
      rpy = nums(origin:match('rpy="([^"]+)"')),
      axis = nums(body:match('<axis%s+xyz="([^"]+)"')),
    }
  end
  return links, joints
end

local function axis_rot(a, q)
  local n = sqrt(a[1] ^ 2 + a[2] ^ 2 + a[3] ^ 2)
  local x, y, z = a[1] / n, a[2] / n, a[3] / n
  local c, s, t = cos(q), sin(q), 1 - cos(q)
  return { t * x * x + c, t * x * y - s * z, t * x * z + s * y,
    t * x * y + s * z, t * y * y + c, t * y * z - s * x,
    t * x * z - s * y, t * y * z + s * x, t * z * z + c }
end

local function apply(R, v)
  return { R[1] * v[1] + R[2] * v[2] + R[3] * v[3], R[4] * v[1] + R[5] * v[2] + R[6] * v[3],
    R[7] * v[1] + R[8] * v[2] + R[9] * v[3] }
end

describe('OP3 model against Config/robots/op3/op3.urdf', function()
  local path = native.root() .. '/Config/robots/op3/op3.urdf'
  local fh = io.open(path, 'r')
  if not fh then
    it('needs Config/robots/op3/op3.urdf (not there yet)', function() pending('no URDF') end)
    return
  end
  fh:close()
  local m = kin.load({ robot = 'op3' })
  local links, joints = read_urdf(path)
  local by_child = {}
  for name, j in pairs(joints) do by_child[j.child] = name end

  -- URDF forward kinematics: world pose (R, p) of every link, body_link at the identity.
  local function urdf_fk(q)
    local poses = {}
    local function pose(link)
      if poses[link] then return poses[link] end
      local jn = by_child[link]
      if not jn then
        poses[link] = { R = { 1, 0, 0, 0, 1, 0, 0, 0, 1 }, p = { 0, 0, 0 } }
        return poses[link]
      end
      local j = joints[jn]
      local P = pose(j.parent)
      local rpy = j.rpy[1] and j.rpy or { 0, 0, 0 }
      local Rj = rpy_rot(rpy[1], rpy[2], rpy[3])
      local idx = m.index[jn]
      if idx and j.axis[1] then Rj = matmul(Rj, axis_rot(j.axis, q[idx + 1])) end
      local o = apply(P.R, j.xyz)
      poses[link] = { R = matmul(P.R, Rj), p = { P.p[1] + o[1], P.p[2] + o[2], P.p[3] + o[3] } }
      return poses[link]
    end
    for name in pairs(links) do pose(name) end
    return poses
  end

  it('has every joint of the robot, with the same axes', function()
    for _, name in ipairs(m.joints) do assert.is_not_nil(joints[name], name) end
  end)

  it('FK of every link and the whole-body COM agree with the URDF chain', function()
    local R = rng(11)
    local worst_p, worst_r, worst_c = 0, 0, 0
    for trial = 1, 50 do
      local q = {}
      for i = 1, m.n do q[i] = trial == 1 and 0 or R(-1, 1) end
      local mine = m:link_poses(q)
      local theirs = urdf_fk(q)
      -- my link frame: torso-aligned at the zero pose, the torso origin carried along; the URDF's
      -- link frame: world-aligned at the zero pose, origin at its joint. Rotations must agree.
      for i, name in ipairs(m.joints) do
        worst_r = math.max(worst_r, rot_dist(mine[i].R, theirs[joints[name].child].R))
      end
      -- anchors: URDF link origin = joint anchor; in my frame, anchor(q) = R_j anchor0 + p_j, where
      -- p_j is the link frame origin and anchor0 the zero-pose anchor relative to the torso origin
      local zero = urdf_fk(setmetatable({}, { __index = function() return 0 end }))
      for i, name in ipairs(m.joints) do
        local T, T0 = theirs[joints[name].child], zero[joints[name].child]
        local a = apply(mine[i].R, T0.p)
        local pm = { a[1] + mine[i][1], a[2] + mine[i][2], a[3] + mine[i][3] }
        worst_p = math.max(worst_p, sqrt((pm[1] - T.p[1]) ^ 2 + (pm[2] - T.p[2]) ^ 2 + (pm[3] - T.p[3]) ^ 2))
      end
      -- COM from the URDF's masses
      local M, s = 0, { 0, 0, 0 }
      for name, l in pairs(links) do
        local T = theirs[name]
        if T and l.mass then
          local c = apply(T.R, l.com)
          for k = 1, 3 do s[k] = s[k] + l.mass * (T.p[k] + c[k]) end
          M = M + l.mass
        end
      end
      local c = m:com(q)
      for k = 1, 3 do worst_c = math.max(worst_c, abs(c[k] - s[k] / M)) end
    end
    print(string.format('# URDF vs kinematics: worst anchor %.3g m, rotation %.3g rad, COM %.3g m',
      worst_p, worst_r, worst_c))
    assert.is_true(worst_p < 1e-9)
    assert.is_true(worst_r < 1e-9)
    assert.is_true(worst_c < 1e-6)
  end)
end)
