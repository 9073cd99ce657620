-- luacheck: std +busted
-- The OP platform's motion configs (Config/OP: walk.lua, keyframes) for both robots it drives,
-- checked offline against that robot's own kinematic model: every walk target reachable and every
-- joint inside the platform's limits at the walk's top speeds, keyframes loadable.
local ffi = require('ffi')
local Config = require('Config')
local kin = require('kinematics')
local Walk = require('Motion.walk')
local keyframe = require('Motion.keyframe')

ffi.cdef('int setenv(const char *name, const char *value, int overwrite);')

-- loads the OP platform's robot, walk and model for OP_ROBOT = robot_name
local function op_platform(robot_name)
  ffi.C.setenv('OP_ROBOT', robot_name, 1)
  Config.reload()
  local robot = Config.load('robot', nil, 'OP')
  return robot, Config.load('walk', nil, 'OP'), kin.load('OP')
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

for _, robot_name in ipairs({ 'darwin', 'op3' }) do
  describe('Config/OP with OP_ROBOT=' .. robot_name, function()
    local robot, params, model
    setup(function() robot, params, model = op_platform(robot_name) end)
    teardown(function()
      ffi.C.setenv('OP_ROBOT', '', 1)
      Config.reload()
    end)

    it('uses its own robot model', function()
      assert.equals(robot_name == 'op3' and 'op3' or 'darwin-op', robot.name)
      -- the OP3 is the simulated robot; the DARwIn-OP's model (Config/OP/kinematics.lua) weighs 3.11 kg
      if robot_name == 'op3' then
        assert.equals(kin.load('Sim').mass, model.mass)
      else
        assert.is_near(3.109, model.mass, 0.001)
      end
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
        assert.is_table(Config.load(concern, nil, 'OP'), concern)
      end
      assert.equals('v4l2', Config.load('camera', nil, 'OP').driver)
    end)

    it('has the keyframe motions of the motion state machine', function()
      keyframe.reload()
      for _, name in ipairs({ 'sit', 'standup_front', 'standup_back' }) do
        local kf = keyframe.load(name, #robot.joints, 'OP')
        assert.is_true(#kf.frames >= 1, name)
      end
    end)
  end)
end
