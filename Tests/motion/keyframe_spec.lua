-- luacheck: std +busted
-- Keyframe files keyed by joint name (Player/Motion/keyframe.lua): the bodies' files load, bad input
-- fails naming the file, the frame and the joint, mirrored poses take their signs from the axes,
-- joints a frame does not name hold.
local Config = require('Config')
local kin = require('kinematics')
local control = require('Motion.control')
local keyframe = require('Motion.keyframe')

local robot = Config.load('robot')
local model = kin.load()
local body = control.keyframe_body(robot, model)
local n = #robot.joints
local ji = body.index
local FILE = 'Config/robots/x/keyframes/bad.lua'

local function check(frames) return keyframe.check({ frames = frames }, FILE, body) end
local function zeros() local t = {} for i = 1, n do t[i] = 0 end return t end

describe('keyframe files', function()
  it("load for the body and drive the joints they name", function()
    for _, name in ipairs({ 'sit', 'standup_front', 'standup_back' }) do
      local kf = keyframe.load(name, body)
      assert.is_true(keyframe.duration(kf) > 0)
      assert.equals(n, #kf.joints, name .. ' names every joint of the OP3')
    end
  end)

  it('fail naming the file, the frame and the joint', function()
    local cases = {
      { { { duration = 1, hardness = 1, q = { l_kne = 0.1 } } },
        "frame 1: joint 'l_kne' in 'q': the body has no such joint" },
      { { { duration = 1, hardness = 1, q = { l_knee = 0 } }, { duration = 1, hardness = 1, q = { l_knee = 0 / 0 } } },
        "frame 2: joint 'l_knee': the angle must be a finite number" },
      { { { duration = 1, hardness = 1, mirror = { l_knee = math.huge } } },
        "frame 1: joint 'l_knee': the angle must be a finite number" },
      { { { hardness = 1, q = { l_knee = 0 } } }, "frame 1: missing field 'duration'" },
      { { { duration = 1, q = { l_knee = 0 } } }, "frame 1: missing field 'hardness'" },
      { { { duration = 1, hardness = 1 } }, "frame 1: missing field 'q'" },
      { { { duration = 1, hardness = 1, mirror = { r_knee = 1 } } },
        "frame 1: joint 'r_knee' in 'mirror': only left-side joints (l_...) are mirrored" },
      { { { duration = 1, hardness = 1, q = { r_knee = 1 }, mirror = { l_knee = 1 } } },
        "frame 1: joint 'r_knee' is named twice" },
      { { { duration = 1, hardness = { l_knee = 2 }, q = { l_knee = 1 } } },
        "frame 1: joint 'l_knee': 'hardness' must be 0..1" },
      { { { duration = 1, hardness = 1, q = { l_knee = 1 }, speed = 2 } }, "frame 1: unknown field 'speed'" },
      { {}, "'frames' is empty" },
    }
    for _, case in ipairs(cases) do
      local ok, err = pcall(check, case[1])
      assert.is_false(ok, case[2])
      assert.matches(FILE .. ': ', err, 1, true)
      assert.matches(case[2], err, 1, true)
    end
    local ok, err = pcall(keyframe.check, {}, FILE, body)
    assert.is_false(ok)
    assert.matches(FILE .. ": missing field 'frames'", err, 1, true)
    -- a missing file names the file too
    ok, err = pcall(keyframe.load, 'no_such_motion', body)
    assert.is_false(ok)
    assert.matches('keyframes/no_such_motion.lua', err, 1, true)
  end)

  it('mirror the left side onto the right with the signs of the axes', function()
    local kf = check({ { duration = 1, hardness = 1, mirror = { l_sho_roll = 0.4, l_knee = 1.2 } } })
    local q, h = zeros(), zeros()
    keyframe.play(kf, 0, zeros(), 0):update(1, q, h)
    -- the OP3's right joints' axes are mirror images with the opposite sense: r = -l
    assert.equals(0.4, q[ji.l_sho_roll])
    assert.equals(-0.4, q[ji.r_sho_roll])
    assert.equals(-1.2, q[ji.r_knee])
    assert.same({ ji.l_sho_roll, ji.l_knee, ji.r_knee, ji.r_sho_roll }, kf.joints)
  end)

  it('interpolate from the start pose; joints a frame does not name hold, others are left alone', function()
    local kf = check({
      { duration = 1, hardness = 0.5, q = { l_knee = 1, head_pan = 0.2 } },
      { duration = 2, hardness = { l_knee = 1 }, q = { l_knee = -1 } },
    })
    local q0 = zeros()
    q0[ji.head_pan] = 0.6
    local p = keyframe.play(kf, 10, q0, 0)
    local q, h = {}, {}
    assert.is_false(p:update(10.5, q, h))
    assert.is_near(0.5, q[ji.l_knee], 1e-9)
    assert.is_near(0.4, q[ji.head_pan], 1e-9)
    assert.is_near(0.25, h[ji.l_knee], 1e-9)
    assert.is_nil(q[ji.r_knee], 'a joint no frame names is not written')
    p:update(11, q, h)
    assert.is_near(1, q[ji.l_knee], 1e-9)
    p:update(12, q, h)
    assert.is_near(0, q[ji.l_knee], 1e-9)
    assert.is_near(0.2, q[ji.head_pan], 1e-9)
    assert.is_true(p:update(13.5, q, h))
    assert.is_near(-1, q[ji.l_knee], 1e-9)
    assert.is_near(1, h[ji.l_knee], 1e-9)
    -- head_pan is not named in frame 2: it holds frame 1's target and hardness
    assert.is_near(0.2, q[ji.head_pan], 1e-9)
    assert.is_near(0.5, h[ji.head_pan], 1e-9)
  end)
end)
