-- luacheck: std +busted
-- Every body's motion configs (Config/robots/<robot>: walk.lua, keyframes) on every platform that
-- carries it (op3, darwin, hoap3), checked offline against the body's own kinematic model: every walk target reachable
-- and every joint inside the limits at the walk's top speeds, keyframes loadable.
local Config = require('Config')
local kin = require('kinematics')
local Walk = require('Motion.walk')
local keyframe = require('Motion.keyframe')
local control = require('Motion.control')

-- the robot, walk and model of a body on a platform
local function body(robot_name, platform)
  local opts = { robot = robot_name, platform = platform }
  return Config.load('robot', nil, opts), Config.load('walk', nil, opts), kin.load(opts)
end

-- walks at (vx, vy, va) for `seconds`; returns ticks with an unreachable IK target and the
-- largest excursion beyond a joint limit (rad)
local function walk_check(robot, params, model, vx, vy, va, seconds)
  local w = Walk.new(params, model):bind(robot)
  local q = {}
  for i = 1, #robot.joints do q[i] = 0 end
  w:set_velocity(vx, vy, va)
  w:start()
  local flagged, beyond = 0, 0
  for _ = 1, math.floor(seconds / robot.period + 0.5) do
    w:advance(robot.period)
    if w:joint_angles(q, nil, robot.period) ~= 0 then flagged = flagged + 1 end
    w:update_com_offset(q)
    for i, name in ipairs(robot.joints) do
      assert(q[i] == q[i], 'NaN joint angle')
      local lim = robot.limits[name]
      beyond = math.max(beyond, lim[1] - q[i], q[i] - lim[2])
    end
  end
  return flagged, beyond
end

-- each body's model mass: op3_reference.txt, darwin_reference.txt, hoap3_reference.txt (kg)
local MASS = { op3 = 3.147, darwin = 2.925, hoap3 = 8.802 }

local CASES = { { 'op3', 'Sim' }, { 'darwin', 'Sim' }, { 'op3', 'OP' }, { 'darwin', 'OP' }, { 'hoap3', 'Sim' } }
for _, case in ipairs(CASES) do
  local robot_name, platform = case[1], case[2]
  local opts = { robot = robot_name, platform = platform }
  describe(robot_name .. ' on ' .. platform, function()
    local robot, params, model
    setup(function() robot, params, model = body(robot_name, platform) end)

    it('uses its own robot model', function()
      assert.equals(robot_name, robot.name)
      assert.is_near(MASS[robot_name], model.mass, 0.001)
    end)

    it('walks at its top speeds with every target reachable and inside the joint limits', function()
      local cases = {
        { params.velLimitX[2], 0, 0 }, { params.velLimitX[1], 0, 0 },
        { 0, params.velLimitY[2], 0 }, { 0, params.velLimitY[1], 0 },
        { 0, 0, params.velLimitA[2] }, { 0.6 * params.velLimitX[2], 0, 0.5 * params.velLimitA[2] },
      }
      for _, c in ipairs(cases) do
        local flagged, beyond = walk_check(robot, params, model, c[1], c[2], c[3], 8)
        local what = string.format('%s at (%.2f, %.2f, %.2f)', robot_name, c[1], c[2], c[3])
        assert.equals(0, flagged, what .. ': unreachable targets')
        assert.is_true(beyond <= 1e-9, string.format('%s: %.3f rad beyond a joint limit', what, beyond))
      end
    end)

    it('has every config the robot processes load', function()
      for _, concern in ipairs({ 'walk', 'camera', 'vision', 'behavior' }) do
        assert.is_table(Config.load(concern, nil, opts), concern)
      end
      assert.equals(platform == 'Sim' and 'sim' or 'v4l2', Config.load('camera', nil, opts).driver)
    end)

    it('has the keyframe motions of the motion state machine', function()
      keyframe.reload()
      -- a body that cannot stand itself up (fallPolicy.standup = false) has no stand-ups
      local policy = params.fallPolicy
      local names = (policy and policy.standup == false) and { 'sit' } or { 'sit', 'standup_front', 'standup_back' }
      for _, name in ipairs(names) do
        local kf = keyframe.load(name, control.keyframe_body(robot, model), robot_name)
        assert.is_true(#kf.frames >= 1, name)
        assert.is_true(#kf.joints >= 1, name)
      end
    end)
  end)
end
