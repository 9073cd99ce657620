-- luacheck: std +busted
-- Kinematics of every body (Config/robots: op3, darwin, the waistbot test body, hubo2plus, hoap3), built from its URDF
-- and robot.lua's chains, through the Lua API: FK(IK(x)) = x over the workspace, known poses,
-- unreachable and NaN targets, limits, look-at (the DARwIn-OP's camera is pitched 45 deg down at
-- the zero pose), arms of any length, a waist, agreement with an independent reading of the URDF,
-- and the OP3's and DARwIn-OP's mass models against their reference data.
local kin = require('kinematics')
local Config = require('Config')
local U = require('Tests.kinematics.urdf_read')

local sin, cos, abs, sqrt, atan2, pi = math.sin, math.cos, math.abs, math.sqrt, math.atan2, math.pi
local matmul, rpy_rot = U.matmul, U.rpy_rot

local BODIES = { 'op3', 'darwin', 'waistbot', 'hubo2plus', 'hoap3' }

-- Where each body's feet and eyes work (torso frame, m and rad): the walking workspace sampled for
-- the leg IK (x, y outward from the zero-pose foot, z above it: half-ranges or ranges; roll, pitch,
-- yaw half-ranges) and the ground points look_at is asked to see. The small bodies share one; the
-- Hubo2+'s legs are 2.5 times longer, its ankle roll turns only +-0.19 rad, and its head tilts
-- +-30 deg on two axes and does not pan (robot.lua), so its eyes see ahead only.
local SMALL = { x = 0.09, y = { -0.03, 0.06 }, z = { 0.02, 0.08 }, roll = 0.3, pitch = 0.3, yaw = 0.6,
  look_x = { 0.3, 4 }, look_y = 1.5 }
local WORKSPACE = {
  -- the HOAP-3's ankles pitch by 60 deg and roll by 25 deg at most, its hips turn inwards by 30 deg
  -- (robot.lua, S1's limits); its steps are 0.06 m at most (walk.lua)
  hoap3 = { x = 0.06, y = { -0.01, 0.05 }, z = { 0.02, 0.06 }, roll = 0.2, pitch = 0.2, yaw = 0.35,
    look_x = { 0.3, 4 }, look_y = 1.5 },
  hubo2plus = { x = 0.15, y = { -0.03, 0.07 }, z = { 0.05, 0.15 }, roll = 0.08, pitch = 0.2, yaw = 0.3,
    look_x = { 2.5, 5 }, look_y = 0.3 },
}

-- Deterministic pseudo-random numbers (LCG) so a failure can be replayed.
local function rng(seed)
  local s = seed
  return function(lo, hi)
    s = (s * 1103515245 + 12345) % 2147483648
    return lo + (hi - lo) * s / 2147483648
  end
end

local function transpose(A) return { A[1], A[4], A[7], A[2], A[5], A[8], A[3], A[6], A[9] } end

-- Angle between two rotations (row-major 3x3), robust near zero.
local function rot_dist(A, B)
  local M = matmul(transpose(A), B)
  local s = sqrt((M[8] - M[6]) ^ 2 + (M[3] - M[7]) ^ 2 + (M[4] - M[2]) ^ 2) / 2
  local c = (M[1] + M[5] + M[9] - 1) / 2
  return atan2(s, c)
end

local function finite(v) return v == v and v ~= math.huge and v ~= -math.huge end

local function dist3(a, b) return sqrt((a[1] - b[1]) ^ 2 + (a[2] - b[2]) ^ 2 + (a[3] - b[3]) ^ 2) end

local function pose_error(p1, p2)
  return dist3(p1, p2), rot_dist(rpy_rot(p1[4], p1[5], p1[6]), rpy_rot(p2[4], p2[5], p2[6]))
end

-- Angle between the camera's optical axis (column 0 of R) and the direction to t.
local function look_error(t, c)
  local d = { t[1] - c[1], t[2] - c[2], t[3] - c[3] }
  local x = { c.R[1], c.R[4], c.R[7] }
  local cr = { d[2] * x[3] - d[3] * x[2], d[3] * x[1] - d[1] * x[3], d[1] * x[2] - d[2] * x[1] }
  return atan2(sqrt(cr[1] ^ 2 + cr[2] ^ 2 + cr[3] ^ 2), d[1] * x[1] + d[2] * x[2] + d[3] * x[3])
end

local function zeros(m)
  local q = {}
  for i = 1, m.n do q[i] = 0 end
  return q
end

-- The sign of a joint's axis along the torso's x, y or z (k = 1, 2, 3).
local function sign(m, joint, k) return m:axis(joint)[k] > 0 and 1 or -1 end

-- Leg angles from canonical ones (about +z, +x, +y, +y, +y, +x of the torso) through the axes.
local function leg_q(m, side, c)
  local q, idx = {}, m.leg_index[side == 'l' and 0 or 1]
  local k_of = { 3, 1, 2, 2, 2, 1 }
  for k = 1, 6 do q[k] = c[k] * sign(m, m.joints[idx[k]], k_of[k]) end
  return q
end

for _, body in ipairs(BODIES) do
  describe('kinematics of ' .. body, function()
    local m = kin.load({ robot = body })
    local leg_len = -m:leg_fk('l', { 0, 0, 0, 0, 0, 0 })[3] -- torso origin to sole, zero pose
    local W = WORKSPACE[body] or SMALL
    local hip_yaw = m.joints[m.leg_index[0][1]]

    it('FK(IK(x)) = x over sampled foot poses of the walking workspace', function()
      local R = rng(42)
      local worst_p, worst_r, n, flagged = 0, 0, 0, 0
      local q, p2 = {}, {}
      for _, side in ipairs({ 'l', 'r' }) do
        local sy = side == 'l' and 1 or -1
        local y0 = m:leg_fk(side, { 0, 0, 0, 0, 0, 0 })[2]
        for _ = 1, 3000 do
          local pose = { R(-W.x, W.x), y0 + sy * R(W.y[1], W.y[2]), -leg_len + R(W.z[1], W.z[2]),
            R(-W.roll, W.roll), R(-W.pitch, W.pitch), R(-W.yaw, W.yaw) }
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
        body, n, flagged, worst_p, worst_r))
      assert.is_true(n > 5400) -- nearly all of this box is reachable within the limits
      assert.is_true(worst_p < 1e-6)
      assert.is_true(worst_r < 1e-6)
    end)

    it('FK(IK(FK(q))) = FK(q) for random joint angles, whatever the axes\' senses', function()
      local R = rng(7)
      local qs, p1, p2 = {}, {}, {}
      local worst_p, worst_r = 0, 0
      for _, side in ipairs({ 'l', 'r' }) do
        for _ = 1, 2000 do
          -- the solver's branch: knee bent backward, |ankle roll| < pi/2, foot pitched less than 90 deg
          local c
          repeat
            c = { R(-0.5, 0.5), R(-0.4, 0.4), R(-1.0, 0.6), R(0.02, 2.0), R(-1.0, 1.0), R(-0.4, 0.4) }
          until abs(c[3] + c[4] + c[5]) < 1.4
          local q = leg_q(m, side, c)
          local inside = true
          for k = 1, 6 do
            local lo, hi = m:limits(m.joints[m.leg_index[side == 'l' and 0 or 1][k]])
            inside = inside and q[k] >= lo and q[k] <= hi
          end
          if inside then
            m:leg_fk(side, q, p1)
            local _, flags = m:leg_ik(side, p1, qs)
            assert.are.equal(0, flags)
            m:leg_fk(side, qs, p2)
            local dp, dr = pose_error(p1, p2)
            worst_p, worst_r = math.max(worst_p, dp), math.max(worst_r, dr)
          end
        end
      end
      assert.is_true(worst_p < 1e-6 and worst_r < 1e-6, string.format('%.3g m %.3g rad', worst_p, worst_r))
    end)

    it('zero pose: the foot stands straight below the hip and IK gives straight legs', function()
      for _, side in ipairs({ 'l', 'r' }) do
        local p = m:leg_fk(side, { 0, 0, 0, 0, 0, 0 })
        -- soles on z = 0 of the reference frame: the foot is origin.z below the torso origin
        assert.is_true(abs(p[3] + m.origin[3]) < 1e-12)
        for k = 4, 6 do assert.is_true(abs(p[k]) < 1e-12) end -- the foot frame is torso-aligned
        local q, flags = m:leg_ik(side, p)
        assert.are.equal(0, flags)
        for k = 1, 6 do assert.is_true(abs(q[k]) < 1e-6, 'joint ' .. k .. ': ' .. q[k]) end
      end
    end)

    it('stays exact while the knee nears straight', function()
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
      -- (a shank off the hip centre along the pitch axes, the Hubo's 0.8 mm, rolls the straight
      -- leg by that offset over its length, the foot kept level)
      for k = 1, 6 do assert.is_true(abs(q[k]) < ((k == 2 or k == 6) and 2e-3 or 1e-6)) end
      local legj = m.leg_index[0]
      assert.is_true(abs(sign(m, m.joints[legj[2]], 1) * q[2] + sign(m, m.joints[legj[6]], 1) * q[6]) < 1e-9)
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
      local lo, hi = m:limits(hip_yaw)
      assert.is_true(lo < 0 and hi > 0)
      local want = math.min(hi + 0.5, 3.0)   -- hip yaw beyond its upper limit: the foot's yaw
      local q, flags = m:leg_ik('l', 0, y0, -leg_len + 0.05, 0, 0, sign(m, hip_yaw, 3) * want)
      assert.are.equal(kin.JOINT_LIMIT, flags)
      assert.is_true(abs(q[1] - hi) < 1e-12)
    end)

    it('look_at points the optical axis at the target', function()
      local R = rng(3)
      local worst, solved = 0, 0
      for _ = 1, 300 do
        local t = { R(W.look_x[1], W.look_x[2]), R(-W.look_y, W.look_y), R(-0.5, -0.1) - m.origin[3] }
        local qh, flags = m:look_at(t)
        if flags == 0 then
          worst, solved = math.max(worst, look_error(t, m:head_fk(qh))), solved + 1
        end
      end
      print(string.format('# %s: look_at %d of 300 ground points within the limits, worst %.3g rad', body,
        solved, worst))
      assert.is_true(solved > 200)
      assert.is_true(worst < 1e-9)
    end)

    it('camera pose: height above the sole, tilts with the torso', function()
      local q = zeros(m)
      local cam = m:camera_pose(q, { 0, 0, 0 })
      local c0 = m:head_fk({ 0, 0 })
      assert.is_true(abs(cam.height - (c0[3] + m.origin[3])) < 1e-12)
      local cp = m:camera_pose(q, { 0, 0.2, 0 }) -- torso pitched forward: the camera moves forward, down
      assert.is_true(abs(cp[1] - (cos(0.2) * c0[1] + sin(0.2) * c0[3])) < 1e-12)
      assert.is_true(abs(cp[3] - (-sin(0.2) * c0[1] + cos(0.2) * c0[3])) < 1e-12)
    end)

    it('legs_ik fills both legs into a whole-body array without garbage', function()
      local q = zeros(m)
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
      -- a per-call allocation of even 16 bytes would be ~300 KiB over 20000 calls; a late side trace
      -- of the JIT may still allocate a little (1.2 KiB seen once on a loaded machine)
      assert.is_true(grown < 16, string.format('%.1f KiB allocated in 20000 calls', grown))
    end)

    it('arm IK of the chain\'s length reaches hand points made by FK', function()
      local R = rng(5)
      local worst, n = 0, 0
      for _, side in ipairs({ 'l', 'r' }) do
        local idx = m.chain_index[side .. 'arm']
        for _ = 1, 100 do
          local qa, qs = {}, {}
          for k = 1, #idx do
            local lo, hi = m:limits(m.joints[idx[k]])
            -- the start: the zero pose, 0.1 rad inside a limit that zero sits on (the HOAP-3's
            -- straight elbow: from there bending is not a first-order motion of the hand)
            qa[k], qs[k] = R(math.max(lo, -1), math.min(hi, 1)), math.min(math.max(0, lo + 0.1), hi - 0.1)
          end
          local h = m:arm_fk(side, qa)
          local _, flags = m:arm_ik(side, h, qs)
          if flags == 0 then worst, n = math.max(worst, dist3(h, m:arm_fk(side, qs))), n + 1 end
        end
      end
      print(string.format('# %s: arm IK (%d joints) solved %d of 200, worst %.3g m', body, m.arm_n[0], n, worst))
      assert.is_true(n >= 190)
      assert.is_true(worst < 1e-4)
    end)

    it('refuses a wrong side, a wrong model and an unknown joint', function()
      assert.has_error(function() m:leg_ik('x', 0, 0, 0, 0, 0, 0) end)
      assert.has_error(function() kin.leg_ik({}, 'l', 0, 0, 0, 0, 0, 0) end)
      assert.has_error(function() m:axis("no_such_joint") end,
        "kinematics: " .. body .. " has no joint 'no_such_joint'")
    end)

    it('agrees with an independent reading of the URDF: axes, every link\'s FK, the COM', function()
      local robot = Config.load('robot', nil, { robot = body })
      local u = U.read(Config.robot_file(robot.description, body))
      local zero = U.fk(u, function() return 0 end)
      for _, name in ipairs(m.joints) do
        local j = assert(u.joints[name], name)
        local a = U.apply(zero[j.child].R, j.axis)
        local n = sqrt(a[1] ^ 2 + a[2] ^ 2 + a[3] ^ 2) -- the file's axes are unit vectors to 6 digits
        assert.is_true(dist3({ a[1] / n, a[2] / n, a[3] / n }, m:axis(name)) < 1e-12, name)
      end
      local R = rng(11)
      local worst_p, worst_r, worst_c = 0, 0, 0
      for trial = 1, 30 do
        local q = {}
        for i = 1, m.n do q[i] = trial == 1 and 0 or R(-1, 1) end
        local mine = m:link_poses(q)
        local theirs = U.fk(u, function(jn) return q[m.index[jn] + 1] end)
        -- my link pose: the displacement of the link from its zero pose (R, p); the URDF's: the
        -- link frame, so R = R_u R_u0^T and p = p_u - R p_u0
        for i, name in ipairs(m.joints) do
          local child = u.joints[name].child
          local T, T0 = theirs[child], zero[child]
          local Rd = matmul(T.R, transpose(T0.R))
          local a = U.apply(Rd, T0.p)
          worst_r = math.max(worst_r, rot_dist(mine[i].R, Rd))
          worst_p = math.max(worst_p, dist3(mine[i], { T.p[1] - a[1], T.p[2] - a[2], T.p[3] - a[3] }))
        end
        local M, s = 0, { 0, 0, 0 }
        for name, l in pairs(u.links) do
          if l.mass then
            local c = U.apply(theirs[name].R, l.com)
            for k = 1, 3 do s[k] = s[k] + l.mass * (theirs[name].p[k] + c[k]) end
            M = M + l.mass
          end
        end
        local c = m:com(q)
        worst_c = math.max(worst_c, dist3(c, { s[1] / M, s[2] / M, s[3] / M }))
      end
      print(string.format('# %s: URDF vs kinematics: worst position %.3g m, rotation %.3g rad, COM %.3g m',
        body, worst_p, worst_r, worst_c))
      assert.is_true(worst_p < 1e-9 and worst_r < 1e-9 and worst_c < 1e-9)
    end)
  end)
end

describe('OP3 model against the reference data', function()
  local m = kin.load({ robot = 'op3' })

  it('whole-body COM at the zero pose is the reference COM', function()
    local c = m:com(zeros(m))
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

  it('camera level at the zero pose, at the reference CAMERA point', function()
    local c = m:head_fk({ 0, 0 })
    assert.is_true(dist3(c, { 0.02325, 0, 0.4939 - m.origin[3] }) < 1e-12)
    assert.is_true(rot_dist(c.R, { 1, 0, 0, 0, 1, 0, 0, 0, 1 }) < 1e-12)
  end)
end)

describe('DARwIn-OP model against the reference data (its own joint convention)', function()
  local m = kin.load({ robot = 'darwin' })
  local robot = Config.load('robot', nil, { robot = 'darwin' })
  -- torso origin (between the hip yaw anchors) in the reference frame
  local o = { -0.005, 0, 0.248152 }

  it('mass and whole-body COM at the zero pose are the reference\'s', function()
    assert.is_true(abs(m.mass - 2.92532) < 1e-5)
    local c = m:com(zeros(m))
    local ref = { -0.01907, 2.0e-05, 0.21413 } -- darwin_reference.txt, reference frame (rounded there)
    for k = 1, 3 do assert.is_true(abs(c[k] + o[k] - ref[k]) < 5e-5, k .. ': ' .. (c[k] + o[k])) end
  end)

  it('the camera looks 45 deg down at head_tilt = 0 and level at +pi/4 (count 2560)', function()
    local c = m:head_fk({ 0, 0 })
    local h = sqrt(0.5) -- (the URDF holds pi/4 to 9 digits)
    assert.is_true(abs(c.R[1] - h) < 1e-8 and abs(c.R[7] + h) < 1e-8)   -- optical axis (0.7071, 0, -0.7071)
    assert.is_true(abs(c.R[3] - h) < 1e-8 and abs(c.R[9] - h) < 1e-8)   -- image up (0.7071, 0, 0.7071)
    local l = m:head_fk({ 0, pi / 4 })
    assert.is_true(rot_dist(l.R, { 1, 0, 0, 0, 1, 0, 0, 0, 1 }) < 1e-9)
    -- the reference: optical centre then at (0.03598, 0, 0.42561)
    assert.is_true(dist3(l, { 0.03598 - o[1], 0, 0.42561 - o[3] }) < 2e-5)
  end)

  it('a squat in the DARwIn-OP\'s signs matches the hand computation', function()
    -- left: hip pitch (-y) +0.4 swings the thigh forward, knee (-y) -0.8 bends it, ankle pitch
    -- (+y) -0.4 keeps the foot flat; thigh and tibia 0.093, hip centre (-0.005, 0.037, 0.2195)
    local q = { 0, 0, 0.4, -0.8, -0.4, 0 }
    local p = m:leg_fk('l', q)
    local want = { 0, 0.037, 0.2195 - 0.186 * cos(0.4) - 0.0335 - o[3] }
    for k = 1, 3 do assert.is_true(abs(p[k] - want[k]) < 1e-12, k .. ': ' .. p[k] .. ' vs ' .. want[k]) end
    for k = 4, 6 do assert.is_true(abs(p[k]) < 1e-12) end
    local pr = m:leg_fk('r', { 0, 0, -0.4, 0.8, 0.4, 0 })   -- the right leg: mirrored signs
    assert.is_true(abs(pr[1] - want[1]) < 1e-12 and abs(pr[2] + want[2]) < 1e-12)
    assert.is_true(abs(pr[3] - want[3]) < 1e-12)
    local qi = m:leg_ik('l', p)
    for k = 1, 6 do assert.is_true(abs(qi[k] - q[k]) < 1e-9) end
  end)

  it('ROBOTIS\' walk-ready counts through the device table give a mirror-symmetric crouch', function()
    -- page 9 "walkready" of motion_4096.bin (darwin_reference.txt), counts for servo ids 1..20
    local counts = { 1498, 2518, 1845, 2248, 2381, 1712, 2048, 2048, 2052, 2044, 1637, 2459, 2653, 1443, 2389,
      1707, 2057, 2039, 2048, 2161 }
    local q = {}
    for _, d in ipairs(robot.devices) do -- one row per servo: its joint, id, direction and zero
      local j = rawget(d, 'joint')
      if j then q[m.index[j] + 1] = d.direction * (counts[d.id] - d.zero) * 2 * pi / 4096 end
    end
    local feet = {}
    for s, side in ipairs({ 'l', 'r' }) do
      local q6 = {}
      for k = 1, 6 do q6[k] = q[m.leg_index[s - 1][k]] end
      feet[s] = m:leg_fk(side, q6)
    end
    local l, r = feet[1], feet[2]
    print(string.format('# walk-ready: feet at x %.4f, y +-%.4f, z %.4f below the torso origin, pitched %.3f rad',
      l[1], l[2], -l[3], l[5]))
    -- mirror images within a count or two, parallel, flat across (roll), the knees bent
    assert.is_true(abs(l[1] - r[1]) < 1e-3 and abs(l[2] + r[2]) < 1e-3 and abs(l[3] - r[3]) < 1e-3)
    assert.is_true(abs(l[5] - r[5]) < 0.01 and abs(l[4]) < 0.02 and abs(r[4]) < 0.02 and abs(l[6]) < 0.01)
    assert.is_true(-l[3] < 0.2481 - 0.015)            -- hips lowered (straight legs: 0.2482)
    assert.is_true(l[5] < -0.1 and l[5] > -0.4)         -- the torso leans forward over flat feet
    assert.is_true(l[1] > 0 and l[2] > 0.030)           -- feet ahead of the torso origin, hips apart
  end)
end)

describe('waistbot: a waist carries the arms and the head', function()
  local m = kin.load({ robot = 'waistbot' })
  local robot = Config.load('robot', nil, { robot = 'waistbot' })

  it('has 23 joints in an order that is not the tree\'s, and arms of 4', function()
    assert.equals(23, m.n)
    assert.equals('waist_yaw', robot.joints[23]) -- the parent of arms and head comes last
    assert.equals(4, m.arm_n[0])
    assert.equals(4, m.arm_n[1])
  end)

  it('turning the waist turns the hands and the camera about its axis, not the feet', function()
    local q = zeros(m)
    q[m.index.waist_yaw + 1] = 0.5
    local qa = { 0.2, -0.3, 0.4, 0.5 }
    local h0, h1 = m:arm_fk('l', qa), m:arm_fk('l', qa, nil, q)
    local a = { -0.001, 0, 0 }   -- the waist axis: vertical through x = -0.001, y = 0
    local function turned(p)
      local x, y = p[1] - a[1], p[2] - a[2]
      return { a[1] + cos(0.5) * x - sin(0.5) * y, a[2] + sin(0.5) * x + cos(0.5) * y, p[3] }
    end
    assert.is_true(dist3(h1, turned(h0)) < 1e-12)
    local c0, c1 = m:head_fk({ 0.1, 0.2 }), m:head_fk({ 0.1, 0.2 }, nil, q)
    assert.is_true(dist3(c1, turned(c0)) < 1e-12)
    assert.is_true(pose_error(m:leg_fk('l', { 0, 0, 0, 0, 0, 0 }, nil, q), m:leg_fk('l', { 0, 0, 0, 0, 0, 0 })) < 1e-15)
    -- the whole-body form agrees: camera_pose with the waist turned
    local cam = m:camera_pose(q, { 0, 0, 0 })
    local c2 = m:head_fk({ 0, 0 }, nil, q)
    assert.is_true(dist3(cam, c2) < 1e-12)
  end)

  it('look_at and arm IK work with the waist turned', function()
    local q = zeros(m)
    q[m.index.waist_yaw + 1] = -0.7
    local R = rng(17)
    local worst_look, worst_arm = 0, 0
    for _ = 1, 100 do
      local t = { R(0.5, 3), R(-1, 1), -0.25 }
      local qh, flags = m:look_at(t, nil, q)
      if flags == 0 then worst_look = math.max(worst_look, look_error(t, m:head_fk(qh, nil, q))) end
      local qa = { R(-1, 1), R(-1, 1), R(-1, 1), R(-1, 1) }
      local h = m:arm_fk('r', qa, nil, q)
      local qs, f2 = m:arm_ik('r', h, { 0, 0, 0, 0 }, q)
      if f2 == 0 then worst_arm = math.max(worst_arm, dist3(h, m:arm_fk('r', qs, nil, q))) end
    end
    assert.is_true(worst_look < 1e-9, worst_look)
    assert.is_true(worst_arm < 1e-4, worst_arm)
  end)
end)

describe('hoap3: a neck roll between the tilt and the camera', function()
  local m = kin.load({ robot = 'hoap3' })
  -- the roll axis: along -x through the tilt's anchor, 0.015 m ahead of and 0.283 m above the torso
  -- origin (hoap3_reference.txt: anchor (-0.02, 0, 0.533), the torso origin at (-0.035, 0, 0.25))
  local ax = { 0.015, 0, 0.283 }
  local function rolled(p, a)   -- p turned by a about -x through ax
    local y, z = p[2] - ax[2], p[3] - ax[3]
    return { p[1], ax[2] + cos(a) * y + sin(a) * z, ax[3] - sin(a) * y + cos(a) * z }
  end

  it('rolling the neck carries the camera about the roll axis', function()
    local q = zeros(m)
    q[m.index.head_roll + 1] = 0.2
    local c0, c1 = m:head_fk({ 0, 0 }), m:head_fk({ 0, 0 }, nil, q)
    assert.is_true(dist3(c0, { 0.065, -0.03, 0.279 }) < 1e-12)   -- the right eye, at the zero pose
    assert.is_true(dist3(c1, rolled(c0, 0.2)) < 1e-12)
    assert.is_true(dist3(m:camera_pose(q, { 0, 0, 0 }), c1) < 1e-12)
  end)

  it('look_at points the optical axis at the target with the neck rolled', function()
    local R = rng(23)
    for _, roll in ipairs({ -0.2, 0, 0.25 }) do
      local q = zeros(m)
      q[m.index.head_roll + 1] = roll
      local worst, solved = 0, 0
      for _ = 1, 200 do
        local t = { R(0.5, 3), R(-1, 1), R(-0.3, 0.1) }
        local qh, flags = m:look_at(t, nil, q)
        if flags == 0 then
          worst, solved = math.max(worst, look_error(t, m:head_fk(qh, nil, q))), solved + 1
        end
      end
      assert.is_true(solved > 100, 'roll ' .. roll .. ': ' .. solved .. ' solved')
      assert.is_true(worst < 1e-9, 'roll ' .. roll .. ': worst ' .. worst)
    end
  end)

  it('weighs the reference\'s 8.80 kg with its COM 0.3 mm ahead of the ankles at the zero pose', function()
    assert.is_near(8.8024, m.mass, 1e-9)
    local c = m:com(zeros(m))
    assert.is_near(0.00027, c[1], 1e-5)           -- torso frame: the ankles at x = 0
    assert.is_near(0.3174 - m.origin[3], c[3], 1e-4)
  end)
end)
