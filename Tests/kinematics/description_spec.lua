-- luacheck: std +busted
-- The committed robot descriptions (Config/robots/<robot>/<robot>.urdf, written by Tools/urdf/gen_urdf.py)
-- against the robot data they were generated from: the same joints as robot.joints, robot.lua's
-- limits, each joint's actuator model (torque, speed, damping, friction), the frames at the place
-- robot.lua gives, the chains' tips, the masses. (The reference files are not read here: only
-- a developer regenerating a description does that.) And bad robot data fails at load, naming
-- the file and the element.
local kin = require('kinematics')
local Config = require('Config')
local native = require('native')
local U = require('Tests.kinematics.urdf_read')

local abs = math.abs

-- total mass of each body's reference data (op3_reference.txt, darwin_reference.txt, waistbot_reference.txt;
-- the Hubo2+: hubo_reference.txt's 38.47 kg plus robot.lua's added_masses, the published 45 kg;
-- the HOAP-3: hoap3_reference.txt, the Fujitsu sheet's full-load masses)
local MASS = { op3 = 3.1475, darwin = 2.92532, waistbot = 3.4475, hubo2plus = 45.0, hoap3 = 8.8024 }

local function bodies()
  local list = {}
  local root = native.root() .. '/Config/robots/'
  local p = io.popen('ls "' .. root .. '"')
  for name in p:lines() do
    -- a folder with only some concerns (hubo2plus's can.lua) is no body yet
    local f = io.open(root .. name .. '/robot.lua')
    if f then
      f:close()
      list[#list + 1] = name
    end
  end
  p:close()
  return list
end

describe('robot descriptions', function()
  it('every body under Config/robots has one and is listed here with its mass', function()
    for _, body in ipairs(bodies()) do
      local robot = Config.load('robot', nil, { robot = body })
      local f = io.open(Config.robot_file(robot.description, body))
      assert.is_not_nil(f, body)
      f:close()
      assert.is_number(MASS[body], body)
    end
  end)

  for body, mass in pairs(MASS) do
    describe(body, function()
      local robot = Config.load('robot', nil, { robot = body })
      local models = Config.load('actuators', nil, { robot = body })
      local u = U.read(Config.robot_file(robot.description, body))
      local zero = U.fk(u, function() return 0 end)

      it('has exactly the joints of robot.joints, with robot.lua\'s limits', function()
        local listed = {}
        for _, j in ipairs(robot.joints) do
          listed[j] = true
          local uj = u.joints[j]
          assert.is_not_nil(uj, j)
          assert.equals('revolute', uj.type)
          local lim = robot.limits[j]
          assert.is_true(abs(uj.lower - lim[1]) < 1e-9 and abs(uj.upper - lim[2]) < 1e-9, j)
        end
        for name, uj in pairs(u.joints) do
          assert.is_true(uj.type == 'fixed' or listed[name], name .. ' is not in robot.joints')
        end
      end)

      it('carries each joint\'s actuator model: torque, speed, damping, friction', function()
        for _, j in ipairs(robot.joints) do
          local uj, model = u.joints[j], robot.actuator[j]
          local a = models[model]
          assert.equals(model, uj.actuator, j)
          assert.is_true(abs(uj.effort - a.torque) < 1e-9 and abs(uj.velocity - a.speed) < 1e-9, j)
          assert.is_true(abs(uj.damping - a.damping) < 1e-9 and abs(uj.friction - a.friction) < 1e-9, j)
        end
      end)

      it('has the frames robot.lua describes, massless, where it says', function()
        for name, f in pairs(robot.frames) do
          local jn = u.by_child[name]
          assert.is_not_nil(jn, name)
          assert.equals('fixed', u.joints[jn].type)
          assert.equals(f.link, u.joints[jn].parent)
          assert.is_true(u.links[name].massless, name)
          -- reference frame = the root frame moved by the root's origin: compare relative to the link
          local P, F = zero[f.link], zero[name]
          local xyz = rawget(f, 'xyz')
          if xyz then
            local l0 = zero[f.link].p
            local d = { F.p[1] - P.p[1], F.p[2] - P.p[2], F.p[3] - P.p[3] }
            -- the link's origin is its joint anchor: frame - anchor in the file = xyz - anchor
            local uj = u.joints[u.by_child[f.link]]
            assert.is_not_nil(uj, f.link)
            local root_shift = { l0[1], l0[2], l0[3] }
            for k = 1, 3 do
              assert.is_true(abs((root_shift[k] + d[k]) - (F.p[k])) < 1e-12)
            end
          end
          local rpy = rawget(f, 'rpy') or { 0, 0, 0 }
          local R = U.rpy_rot(rpy[1], rpy[2], rpy[3])
          for k = 1, 9 do assert.is_true(abs(F.R[k] - R[k]) < 1e-8, name) end
        end
      end)

      it('names frames for every chain tip, the soles level and below the ankles', function()
        for name, c in pairs(robot.chains) do assert.is_not_nil(zero[c.tip], name .. ': ' .. c.tip) end
        local l, r = zero.l_sole, zero.r_sole
        assert.is_true(abs(l.p[3] - r.p[3]) < 1e-12 and abs(l.p[1] - r.p[1]) < 1e-12 and abs(l.p[2] + r.p[2]) < 1e-12)
        for k = 1, 9 do assert.is_true(abs(l.R[k] - (k % 4 == 1 and 1 or 0)) < 1e-12) end
        -- the sole frame lies in the plane of the soles: the root's height above the ground at zero
        local m = kin.load({ robot = body })
        assert.is_true(abs(m.origin[3] + l.p[3]) < 1e-12)
      end)

      it('weighs what its reference data says', function()
        local M = 0
        for _, l in pairs(u.links) do M = M + (l.mass or 0) end
        assert.is_true(abs(M - mass) < 1e-4, string.format('%.5f', M))
        assert.is_true(abs(kin.load({ robot = body }).mass - M) < 1e-9)
      end)
    end)
  end
end)

describe('bad robot data fails at load, naming the file and the element', function()
  local op3 = Config.export('robot', { robot = 'op3' })
  local urdf = Config.robot_file(op3.description, 'op3')
  local tmp = native.root() .. '/build/tmp'
  os.execute('mkdir -p "' .. tmp .. '"')

  -- a fresh plain copy of the OP3's robot config to break (Config.export builds one per call)
  local function copy() return Config.export('robot', { robot = 'op3' }) end

  local function fails(robot, file, ...)
    local m, err = kin.new(robot, file or urdf, 'robots/x/robot.lua')
    assert.is_nil(m)
    for _, part in ipairs({ ... }) do
      assert.is_truthy(err:find(part, 1, true), 'expected "' .. part .. '" in: ' .. tostring(err))
    end
    return err
  end

  it('a joint of robot.joints that the URDF does not have', function()
    local r = copy()
    r.joints[3] = 'l_shoulder'
    fails(r, nil, 'op3.urdf', "no joint 'l_shoulder'", 'robots/x/robot.lua')
  end)

  it('a URDF joint missing from robot.joints', function()
    local r = copy()
    table.remove(r.joints, 20)
    r.chains.rarm = nil
    fails(r, nil, 'op3.urdf', "joint 'r_el' is not in joints")
  end)

  it('an unknown joint or tip in a chain, an unknown chain', function()
    local r = copy()
    r.chains.larm.joints = { 'l_sho_pitch', 'l_elbow' }
    fails(r, nil, 'robots/x/robot.lua', 'chains.larm', "unknown joint 'l_elbow'")
    r = copy()
    r.chains.head.tip = 'eye'
    fails(r, nil, 'chains.head', "tip 'eye'", 'op3.urdf')
    r = copy()
    r.chains.tail = { tip = 'camera_link' }
    fails(r, nil, 'chains.tail', 'unknown chain')
  end)

  it('a chain the IK cannot serve: out of order, short, a tip off its last link, no look-at', function()
    local r = copy()
    r.chains.lleg.joints = { 'l_hip_yaw', 'l_hip_pitch', 'l_hip_roll', 'l_knee', 'l_ank_pitch', 'l_ank_roll' }
    fails(r, nil, "chain 'lleg'", "'l_hip_pitch' does not hang from the chain's previous joint 'l_hip_yaw'")
    r = copy()
    r.chains.rleg.joints = { 'r_hip_yaw', 'r_hip_roll', 'r_hip_pitch', 'r_knee', 'r_ank_pitch' }
    r.chains.rleg.tip = 'r_ank_pitch_link' -- a link may be a tip too
    fails(r, nil, "chain 'rleg'", 'needs 6 joints')
    r = copy()
    r.chains.lleg.tip = 'r_sole'
    fails(r, nil, 'chains.lleg', "tip 'r_sole' is on link 'r_ank_roll_link'")
    r = copy()
    r.chains.head = { joints = { 'head_tilt', 'l_sho_pitch' }, tip = 'l_sho_pitch_link' }
    fails(r, nil, "chain 'head'", 'does not hang from')
    r = copy()
    -- two horizontal axes make a two-tilt head (the Hubo's neck), whose camera must not look
    -- along either axis; two parallel ones are no head at all
    r.chains.head = { joints = { 'l_sho_pitch', 'l_sho_roll' }, tip = 'l_sho_roll_link' }
    fails(r, nil, "chain 'head'", 'lies along a tilt axis')
    r = copy()
    r.chains.head = { joints = { 'l_hip_pitch', 'l_knee' }, tip = 'l_knee_link' }
    fails(r, nil, "chain 'head'", "pan joint 'l_hip_pitch': axis must be along z")
    r = copy()
    r.chains.lleg.joints = { 'l_hip_roll', 'l_hip_yaw', 'l_hip_pitch', 'l_knee', 'l_ank_pitch', 'l_ank_roll' }
    fails(r, nil, "chain 'lleg'")
  end)

  it('a URDF whose joints form a cycle, or that is missing', function()
    local path = tmp .. '/cycle.urdf'
    local f = assert(io.open(urdf))
    local text = f:read('*a')
    f:close()
    -- l_hip_roll_link made the child of the left ankle as well
    text = text:gsub('</robot>', '<joint name="loop" type="revolute"><parent link="l_ank_roll_link"/>' ..
      '<child link="l_hip_roll_link"/><axis xyz="1 0 0"/><limit lower="-1" upper="1" effort="1" velocity="1"/>' ..
      '</joint></robot>')
    f = assert(io.open(path, 'w'))
    f:write(text)
    f:close()
    local r = copy()
    r.joints[#r.joints + 1] = 'loop'
    fails(r, path, 'cycle.urdf', "link 'l_hip_roll_link' is the child of two joints", 'cycle')
    os.remove(path)
    fails(copy(), tmp .. '/none.urdf', 'none.urdf', 'cannot open')
  end)
end)
