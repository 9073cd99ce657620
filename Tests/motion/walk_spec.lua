-- luacheck: std +busted
-- The walk generator alone (no robot): LIPM solution, foot placement, limits, start and stop.
local lipm = require('Motion.lipm')
local Walk = require('Motion.walk')
local fixture = require('Tests.motion.walk_fixture')

local robot, params, model, dt, copy = fixture.robot, fixture.params, fixture.model, fixture.dt, fixture.copy

describe('lipm.solve', function()
  local T, t1, t2, tz = 0.25, 0.025, 0.225, 0.165
  local c = lipm.solve(0.01, 0.035, -0.005, T, t1, t2, tz)

  it('meets the boundary conditions', function()
    local x0 = lipm.eval(c, 0)
    local x1 = lipm.eval(c, T)
    assert.is_near(0.01, x0, 1e-12)
    assert.is_near(-0.005, x1, 1e-12)
  end)

  it('obeys the pendulum equation x\'\' = (x - p) / tZmp^2 on every piece', function()
    local h = 1e-4
    for _, t in ipairs({ 0.01, 0.02, 0.05, 0.1, 0.2, 0.22, 0.23, 0.24 }) do
      local xm = lipm.eval(c, t - h)
      local x, _, p = lipm.eval(c, t)
      local xp = lipm.eval(c, t + h)
      local acc = (xp - 2 * x + xm) / (h * h)
      assert.is_near((x - p) / (tz * tz), acc, 1e-3)
    end
  end)

  it('keeps position and velocity continuous at the knots', function()
    for _, tk in ipairs({ t1, t2 }) do
      local xa, va = lipm.eval(c, tk - 1e-9)
      local xb, vb = lipm.eval(c, tk + 1e-9)
      assert.is_near(xa, xb, 1e-8)
      assert.is_near(va, vb, 1e-6)
    end
  end)

  it('lays out the ZMP as three linear pieces', function()
    assert.is_near(0.01, lipm.zmp(c, 0), 1e-12)
    assert.is_near(0.035, lipm.zmp(c, t1), 1e-12)
    assert.is_near(0.035, lipm.zmp(c, 0.5 * (t1 + t2)), 1e-12)
    assert.is_near(-0.005, lipm.zmp(c, T), 1e-12)
  end)
end)

-- runs a walk for `seconds` at a velocity, returning the walk and the smallest foot spacing seen
local function run(vx, vy, va, seconds, p)
  local w = Walk.new(p or params, model):bind(robot)
  local q = {}
  for i = 1, #robot.joints do q[i] = 0 end
  w:set_velocity(vx, vy, va)
  w:start()
  local flagged, min_gap, maxdv = 0, math.huge, 0
  local last_com
  for _ = 1, math.floor(seconds / dt + 0.5) do
    w:advance(dt)
    if w:joint_angles(q, nil, dt) ~= 0 then flagged = flagged + 1 end
    w:update_com_offset(q)
    local rel = Walk.pose_relative(w.uLeft, w.uRight)
    min_gap = math.min(min_gap, rel[2])
    if last_com then maxdv = math.max(maxdv, math.abs(w.com[1] - last_com) / dt) end
    last_com = w.com[1]
    for i = 1, #q do assert(q[i] == q[i], 'NaN joint angle') end
  end
  return w, { flagged = flagged, min_gap = min_gap, max_com_speed = maxdv }
end

describe('walk', function()
  it('walks forward at the commanded speed (odometry) with every IK target reachable', function()
    local w, s = run(0.25, 0, 0, 10)
    local d = w.uTorso[1]
    -- the speed ramps up at accLimit; after that it is 0.25 m/s
    local ramp = 0.25 / params.accLimit[1]
    assert.is_near(0.25 * (10 - ramp / 2), d, 0.08)
    assert.is_near(0, w.uTorso[2], 0.01)
    assert.equals(0, s.flagged)
    assert.is_true(s.min_gap >= params.stepLimitY[1] - 1e-9)
  end)

  it('walks sideways, backwards and turns on the spot', function()
    local w = run(0, 0.1, 0, 6)
    assert.is_true(w.uTorso[2] > 0.4, 'sideways ' .. w.uTorso[2])
    assert.is_near(0, w.uTorso[1], 0.02)
    w = run(-0.1, 0, 0, 6)
    assert.is_true(w.uTorso[1] < -0.4, 'backwards ' .. w.uTorso[1])
    w = run(0, 0, 1.0, 3)
    -- a short run: the heading has not wrapped yet
    local a = w.uTorso[3]
    assert.is_true(math.abs(a) > 1.5, 'turned ' .. a)
    assert.is_near(0, w.uTorso[1], 0.05)
  end)

  it('clamps velocity commands to the limits and refuses NaN', function()
    local w = Walk.new(params, model)
    local vx, vy, va = w:set_velocity(10, 0, 0)
    assert.is_near(params.velLimitX[2], vx, 1e-12)
    assert.equals(0, vy)
    assert.equals(0, va)
    vx = w:set_velocity(-10, 0, 0)
    assert.is_near(params.velLimitX[1], vx, 1e-12)
    local ok, err = w:set_velocity(0 / 0, 0, 0)
    assert.is_nil(ok)
    assert.matches('finite', err)
    assert.is_near(params.velLimitX[1], w.cmd[1], 1e-12) -- the refused command changed nothing
  end)

  it('starts from and stops into the stance with the feet together', function()
    local w = Walk.new(params, model):bind(robot)
    w:set_velocity(0.2, 0, 0.3)
    w:start()
    for _ = 1, 300 do w:advance(dt) end
    w:stop()
    local n = 0
    while w:advance(dt) do
      n = n + 1
      assert.is_true(n < 600, 'did not stop within 600 ticks')
    end
    local rel = Walk.pose_relative(w.uLeft, w.uRight)
    assert.is_near(0, rel[1], 1e-6)
    assert.is_near(2 * params.footY, rel[2], 1e-6)
    assert.is_near(0, rel[3], 1e-6)
    assert.is_false(w:is_active())
    -- stance: the COM sits between the feet
    local mid = Walk.interp(0.5, w.uLeft, w.uRight)
    assert.is_near(mid[2], w.com[2], 1e-6)
  end)

  it('keeps the COM reference continuous from step to step at a steady speed', function()
    local _, s = run(0.25, 0, 0, 6)
    -- a jump in position would show as a speed far above the walking speed
    assert.is_true(s.max_com_speed < 0.6, 'COM speed ' .. s.max_com_speed)
  end)

  it('turns fast in shorter steps, the feet\'s relative yaw swinging about zero within the step limits', function()
    local p = copy(params)
    p.turnToeIn, p.turnStep, p.stepLimitA = 1.0, { tStep = 0.2, va = { 1.5, 2.0 } }, { -0.5, 0.5 }
    -- the step's period from the turning rate: the walk's below va[1], turnStep's above va[2]
    assert.is_near(p.tStep, Walk.step_period(p, { 0.1, 0, 1.0 }), 1e-12)
    assert.is_near(0.5 * (p.tStep + 0.2), Walk.step_period(p, { 0, 0, -1.75 }), 1e-12)
    assert.is_near(0.2, Walk.step_period(p, { 0, 0, 2.4 }), 1e-12)
    local w = Walk.new(p, model):bind(robot)
    w:set_velocity(0, 0, 2.0)
    w:start()
    local lo, hi, steps, a0 = 0, 0, 0, nil
    for k = 1, math.floor(4 / dt) do
      w:advance(dt)
      if k * dt > 2 then
        if not a0 then a0, steps = w.uTorso[3], w.stats.steps end
        local rel = Walk.pose_relative(w.uLeft2, w.uRight2)[3] -- the left foot's yaw against the right's
        lo, hi = math.min(lo, rel), math.max(hi, rel)
      end
    end
    -- steady at 2 rad/s: 0.2 s steps, the closing foot toed in as far as the opening one is out
    assert.is_near(10, w.stats.steps - steps, 1)
    assert.is_near(0.4, hi, 0.02)
    assert.is_near(-0.4, lo, 0.02)
    -- 2 s at 2 rad/s from a0 (the heading wraps: count whole turns through its sine and cosine)
    local a = w.uTorso[3]
    assert.is_near(math.cos(a0 + 4), math.cos(a), 0.1)
    assert.is_near(math.sin(a0 + 4), math.sin(a), 0.1)
  end)

  it('leads the hip yaw command by hipYawLead x its rate while stepping', function()
    local function walk_with(lead)
      local p = copy(params)
      p.hipYawLead = lead
      local w = Walk.new(p, model):bind(robot)
      w:set_velocity(0, 0, 1.0)
      w:start()
      local q, trace = {}, {}
      for i = 1, #robot.joints do q[i] = 0 end
      for _ = 1, 200 do
        w:advance(dt)
        w:joint_angles(q, nil, dt)
        trace[#trace + 1] = { q[w.legs[Walk.LEFT][1]], q[w.legs[Walk.RIGHT][1]] }
      end
      return trace
    end
    local plain, led = walk_with(0), walk_with(0.04)
    local moved = 0
    for k = 2, #plain do
      for side = 1, 2 do
        local rate = (plain[k][side] - plain[k - 1][side]) / dt
        assert.is_near(plain[k][side] + 0.04 * rate, led[k][side], 1e-9)
        moved = math.max(moved, math.abs(rate))
      end
    end
    assert.is_true(moved > 1, 'the hip yaws turned at ' .. moved .. ' rad/s')
  end)

  it('takes parameter changes while walking', function()
    local p = copy(params)
    local w = Walk.new(p, model):bind(robot)
    w:set_velocity(0.1, 0, 0)
    w:start()
    for _ = 1, 100 do w:advance(dt) end
    local steps = w.stats.steps
    p.tStep = 0.5
    for _ = 1, 250 do w:advance(dt) end
    -- 2 s at 0.5 s per step: about 4 steps (at 0.25 s it would be 8)
    assert.is_true(w.stats.steps - steps <= 5, 'steps ' .. (w.stats.steps - steps))
  end)
end)

describe('walk tilt feedback', function()
  -- the joint angles at stance with the IMU reading `pitch` over the planned posture, `k` the gain
  local function stance_angles(k, pitch, support)
    local p = copy(params)
    p.feedback.ankle, p.feedback.knee, p.feedback.hip, p.feedback.arm = { 0, 0 }, 0, { 0, 0 }, { 0, 0 }
    p.feedback.torso = { 0, 0 }
    p.feedback.tilt, p.feedback.tiltTimeConstant = { 0, k }, 0.05
    local w = Walk.new(p, model):bind(robot)
    w:advance(dt)
    local q = {}
    local sensors = { gyro = { 0, 0, 0 }, angle = { 0, p.bodyTilt + pitch, 0 } }
    for _ = 1, 200 do w:joint_angles(q, sensors, dt, support) end -- 1.6 s: the low-pass has settled
    return q, w
  end

  it('turns both ankles by gain x the torso pitch error at stance, nothing at gain 0', function()
    local q0, w = stance_angles(0, -0.1)
    local q1 = stance_angles(1.0, -0.1)
    for side = Walk.LEFT, Walk.RIGHT do
      local legi = w.legs[side]
      local ap = legi[5]
      -- a rotation of -0.1 rad about the torso's y axis through the joint's axis (restoring)
      assert.is_near(-0.1 * w.ay[ap], q1[ap] - q0[ap], 1e-3)
      for k = 1, 4 do assert.is_near(q0[legi[k]], q1[legi[k]], 1e-12) end
    end
  end)

  it('stays off under a kick that names its support leg (the kick tilts the torso on purpose)', function()
    local q0 = stance_angles(0, -0.2, Walk.LEFT)
    local q1 = stance_angles(1.0, -0.2, Walk.LEFT)
    for i, v in pairs(q0) do assert.is_near(v, q1[i], 1e-12) end
  end)
end)
