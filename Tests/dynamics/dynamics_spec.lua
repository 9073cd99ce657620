-- luacheck: std +busted
-- The rigid-body model (Lib/dynamics.lua over Modules/dynamics, Pinocchio) of every body through
-- the Lua API, in robot.lua's joint order: the total mass against the URDF and the documented
-- figures, the centre of mass and the soles against Modules/kinematics (another implementation, the
-- same joint order), Jacobian columns of named joints against differences of the pose, the base
-- given as roll-pitch-yaw or as a quaternion, gravity on the base = the weight, and the refusals.
local dynamics = require('dynamics')
local kin = require('kinematics')
local Config = require('Config')
local U = require('Tests.kinematics.urdf_read')

local abs, max = math.abs, math.max

local BODIES = { 'op3', 'darwin', 'waistbot', 'hubo2plus' }
-- the masses the README gives for the bodies it documents (kg)
local DOCUMENTED = { op3 = 3.15, hubo2plus = 45.0 }

-- joint angles in +-0.8 rad from LuaJIT's seeded generator (the same sequence on every run)
local function random_q(n)
  local q = {}
  for i = 1, n do q[i] = 1.6 * math.random() - 0.8 end
  return q
end

local function dist(a, b)
  return max(abs(a[1] - b[1]), abs(a[2] - b[2]), abs(a[3] - b[3]))
end

describe('dynamics', function()
  for _, body in ipairs(BODIES) do
    describe(body, function()
      local m = dynamics.load({ robot = body })
      local robot = Config.load('robot', nil, { robot = body })
      local km = kin.load({ robot = body })
      math.randomseed(31)

      it('has the joints of robot.lua in their order, and a floating base', function()
        assert.are.same(robot.joints, m.joints)
        assert.equal(#robot.joints, m.n)
        assert.equal(m.n + 6, m.nv)
      end)

      it("weighs what its URDF's links weigh", function()
        local urdf = U.read(Config.robot_file(robot.description, body))
        local sum = 0
        for _, link in pairs(urdf.links) do sum = sum + (link.mass or 0) end
        assert.is_true(abs(m.mass - sum) < 1e-9, ('%.6f vs %.6f'):format(m.mass, sum))
        assert.is_true(abs(m.mass - km.mass) < 1e-9)
        if DOCUMENTED[body] then assert.is_true(abs(m.mass - DOCUMENTED[body]) < 0.01, tostring(m.mass)) end
      end)

      it('puts the centre of mass and the soles where the kinematics does', function()
        for _ = 1, 5 do
          local q = random_q(m.n)
          m:set(q)
          local c = km:com(q)
          assert.is_true(dist(m:com(), c) < 1e-9, 'com')
          if km.leg_index[0][1] then
            local q6 = {}
            for k, j in ipairs(km.leg_index[0]) do q6[k] = q[j] end
            local zq = {}
            for i = 1, m.n do zq[i] = 0 end
            for k, j in ipairs(km.leg_index[0]) do zq[j] = q6[k] end
            m:set(zq)
            assert.is_true(dist(m:pose('l_sole'), km:leg_fk('l', q6)) < 1e-9, 'l_sole')
          end
        end
      end)

      it('has Jacobian columns = differences of the pose, joint by joint in robot order', function()
        local q = random_q(m.n)
        local base = { 0.1, -0.2, 0.3, 0.2, -0.1, 0.5 }
        local frame = m.joints[#m.joints]
        m:set(q, base)
        local J, Jc = m:jacobian(frame), m:com_jacobian()
        local h, err = 1e-6, 0
        for i = 1, m.n do
          local qi = q[i]
          q[i] = qi + h
          m:set(q, base)
          local pp, cp = m:pose(frame), m:com()
          q[i] = qi - h
          m:set(q, base)
          local pm, cm = m:pose(frame), m:com()
          q[i] = qi
          for k = 1, 3 do
            err = max(err, abs((pp[k] - pm[k]) / (2 * h) - J[k][6 + i]))
            err = max(err, abs((cp[k] - cm[k]) / (2 * h) - Jc[k][6 + i]))
          end
        end
        assert.is_true(err < 1e-6, 'max error ' .. err)
      end)

      it('takes the base as roll-pitch-yaw or as a quaternion', function()
        local q = random_q(m.n)
        local half = 0.35
        m:set(q, { 0.1, 0.2, 0.3, 0, 0, 2 * half })
        local a = m:pose('l_sole')
        m:set(q, { 0.1, 0.2, 0.3, 0, 0, math.sin(half), math.cos(half) })
        local b = m:pose('l_sole')
        assert.is_true(dist(a, b) < 1e-12)
        for k = 1, 9 do assert.is_true(abs(a.R[k] - b.R[k]) < 1e-12) end
      end)

      it('holds its weight on the upright base: a force m g; at rest the nonlinear effects are gravity', function()
        m:set(random_q(m.n))
        local g = m:gravity()
        assert.is_true(abs(g[3] - m.mass * 9.81) < 1e-9, tostring(g[3]))
        assert.is_true(abs(g[1]) < 1e-9 and abs(g[2]) < 1e-9)
        local M, h = m:mass_matrix(), m:nonlinear()
        assert.equal(m.nv, #M)
        assert.is_true(abs(M[1][1] - m.mass) < 1e-9)
        for c = 1, m.nv do assert.is_true(abs(h[c] - g[c]) < 1e-9) end
      end)
    end)
  end

  describe('refuses', function()
    local m = dynamics.load({ robot = 'hubo2plus' })
    local q = {}
    for i = 1, m.n do q[i] = 0 end

    it('an unknown frame, naming it', function()
      m:set(q)
      assert.has_error(function() m:pose('r_plam') end, "dynamics: hubo2plus: no frame 'r_plam' in the model")
    end)

    it('a NaN angle, naming the joint, and keeps the state', function()
      m:set(q)
      local before = m:pose('r_palm')
      q[13] = 0 / 0
      local ok, err = pcall(m.set, m, q)
      q[13] = 0
      assert.is_false(ok)
      assert.truthy(err:find('joint REB angle is not finite', 1, true), err)
      assert.are.same(before, m:pose('r_palm'))
    end)

    it('a base of the wrong size, an unknown reference frame', function()
      assert.has_error(function() m:set(q, { 0, 0, 0 }) end)
      assert.has_error(function() m:jacobian('r_palm', 'body') end)
    end)

    it('a joint order that is not the URDF', function()
      local robot = { name = 'x', joints = { 'WST', 'NK1' } }
      local path = Config.robot_file('hubo2plus.urdf', 'hubo2plus')
      local model, err = dynamics.new(robot, path, 'test config')
      assert.is_nil(model)
      assert.truthy(err:find('test config', 1, true) and err:find('is missing from the joint order', 1, true), err)
    end)
  end)
end)
