-- luacheck: std +busted
-- The capture point's error from the IMU (Player/Motion/capture.lua) on the walk generator alone:
-- the tilt and its rate, and the accelerometer's shove that the tilt does not see.
local Walk = require('Motion.walk')
local capture = require('Motion.capture')
local fixture = require('Tests.motion.walk_fixture')

local params, model, dt, copy = fixture.params, fixture.model, fixture.dt, fixture.copy

local G = 9.81

-- a walk standing upright at the origin (not stepping) with velocityLeak `leak`, and its capture
-- extension
local function walk(leak)
  local p = copy(params)
  p.stepAdjust.velocityLeak = leak
  local w = Walk.new(p, model)
  local cap = w:extend(capture.new())
  return w, p, cap
end

-- sensors of an upright torso with pitch bodyTilt, accelerating by (ax, ay) in the heading frame
local function sensors(p, ax, ay, roll)
  roll = roll or 0
  local pitch = p.bodyTilt
  -- the specific force (a + g up) in the torso frame: R^T (ax, ay, g), R = Ry(pitch) Rx(roll)
  local cp, sp, cr, sr = math.cos(pitch), math.sin(pitch), math.cos(roll), math.sin(roll)
  local x1 = cp * ax - sp * G
  local z1 = sp * ax + cp * G
  return { angle = { roll, pitch, 0 }, acc = { x1, cr * ay + sr * z1, -sr * ay + cr * z1 } }
end

describe('capture point error', function()
  it('is the tilt times the COM height plus its rate times tZmp, without the accelerometer', function()
    local w, p, cap = walk(0)
    local h = p.tZmp * p.tZmp * G
    cap:sense(w, sensors(p, 0, 0, -0.1), { -0.5, 0.2, 0 }, dt)
    assert.is_near(h * math.sin(0.1) + p.tZmp * h * 0.5, cap.err[2], 1e-9) -- rolled left: +y
    assert.is_near(p.tZmp * h * 0.2, cap.err[1], 1e-9)
  end)

  it('sees a shove sideways (the accelerometer integrated against the plan) while walking', function()
    local w, p, cap = walk(0.6)
    w:set_velocity(0.2, 0, 0)
    w:start()
    w:advance(dt)
    -- the plan's own motion: the accelerometer reads it, the error stays small
    for _ = 1, 20 do
      local v0 = { w.comd[1], w.comd[2] }
      w:advance(dt)
      local a = sensors(p, (w.comd[1] - v0[1]) / dt, (w.comd[2] - v0[2]) / dt)
      cap:sense(w, a, { 0, 0, 0 }, dt)
    end
    assert.is_true(math.abs(cap.err[2]) < 1e-3)
    -- 0.1 s of 5 m/s^2 to the left on top of the plan: 0.5 m/s less the leak
    for _ = 1, math.floor(0.1 / dt + 0.5) do
      local v0 = { w.comd[1], w.comd[2] }
      w:advance(dt)
      cap:sense(w, sensors(p, (w.comd[1] - v0[1]) / dt, (w.comd[2] - v0[2]) / dt + 5), { 0, 0, 0 }, dt)
    end
    assert.is_near(0.5 * p.tZmp, cap.err[2], 0.1 * 0.5 * p.tZmp)
    assert.is_true(math.abs(cap.err[1]) < 0.01)
    -- and forgets it with the leak (an offset of the sensor winds nothing up)
    for _ = 1, math.floor(3 / dt) do
      local v0 = { w.comd[1], w.comd[2] }
      w:advance(dt)
      cap:sense(w, sensors(p, (w.comd[1] - v0[1]) / dt, (w.comd[2] - v0[2]) / dt), { 0, 0, 0 }, dt)
    end
    assert.is_true(math.abs(cap.err[2]) < 0.01 * 0.5 * p.tZmp)
  end)

  -- One step of a walk (standing: not started) tipped left by `roll`, with capture gains kc (ankle)
  -- and kh (hip) and only those feedback terms, `gate` the stepAdjust keys to set: the joint angles
  -- and the walk.
  local function capture_angles(kc, kh, roll, stand, gate)
    local robot = fixture.robot
    local w, p, cap = walk(0)
    for k, v in pairs(gate or {}) do p.stepAdjust[k] = v end
    p.feedback.capture, p.feedback.captureHip = { kc, 0 }, { kh, 0 }
    p.feedback.ankle, p.feedback.hip, p.feedback.tilt = { 0, 0 }, { 0, 0 }, { 0, 0 }
    w:bind(robot)
    if not stand then w:start() end
    w:advance(dt)
    local q = {}
    for i = 1, #robot.joints do q[i] = 0 end
    local s = sensors(p, 0, 0, -roll)
    s.gyro, s.position = { 0, 0, 0 }, nil
    w:joint_angles(q, s, dt)
    return q, w, cap
  end

  it('turns the ankles and hips against it (feedback.capture, captureHip)', function()
    local robot = fixture.robot
    local ji = {}
    for i, n in ipairs(robot.joints) do ji[n] = i end
    -- walking, tipped left by 0.2 rad: the capture point's error is +y, beyond the dead band; the
    -- same sensors with and without the gains (standing: none)
    local function angles(kc, kh, stand)
      local q, w, cap = capture_angles(kc, kh, 0.2, stand)
      return q, cap.err[2], w.support == Walk.LEFT and 'l_' or 'r_'
    end
    local q0, e, sup = angles(0, 0)
    local q1 = angles(2, 3)
    assert.is_true(e > params.stepAdjust.deadband[2] + 0.01)
    assert.are.same(angles(0, 0, true), angles(2, 3, true))
    for _, side in ipairs({ 'l_', 'r_' }) do
      local ank, hip = ji[side .. 'ank_roll'], ji[side .. 'hip_roll']
      -- the support leg's: rotations about the torso's x axis through each joint's axis
      local k = side == sup and 1 or 0
      local ax = model:axis(robot.joints[ank])[1]
      local db = params.stepAdjust.deadband[2]
      assert.is_near(-2 * (e - db) * ax * k, q1[ank] - q0[ank], 1e-9)
      ax = model:axis(robot.joints[hip])[1]
      assert.is_near(-3 * (e - db) * ax * k, q1[hip] - q0[hip], 1e-9)
    end
  end)

  it('activates smoothly between activateFrom and activateFull', function()
    assert.are.equal(0, capture.activation(0.02, 0.03, 0.05))
    assert.are.equal(0, capture.activation(0.03, 0.03, 0.05))
    assert.is_near(0.5, capture.activation(0.04, 0.03, 0.05), 1e-12)
    assert.are.equal(1, capture.activation(0.05, 0.03, 0.05))
    assert.are.equal(1, capture.activation(0.2, 0.03, 0.05))
    assert.are.equal(1, capture.activation(0, 0, 0)) -- full 0: no gate
    local last = 0
    for i = 1, 99 do
      local g = capture.activation(0.03 + 0.0002 * i, 0.03, 0.05)
      assert.is_true(g > last and g < 1)
      last = g
    end
    -- no step at either end: the slope is 0 there
    assert.is_true(capture.activation(0.0301, 0.03, 0.05) < 1e-4)
    assert.is_true(capture.activation(0.0499, 0.03, 0.05) > 1 - 1e-4)
  end)

  it('acts on the ankles and hips only beyond the errors of normal walking (the activation)', function()
    local robot = fixture.robot
    local ji = {}
    for i, n in ipairs(robot.joints) do ji[n] = i end
    -- walking, tipped left by `roll`, capture gains 2 (ankle) and 3 (hip): the joints' change from
    -- the same walk without the gains
    local function change(roll, from, full)
      local gate = { activateFrom = { 0, from }, activateFull = { 0, full } }
      local q0 = capture_angles(0, 0, roll, false, gate)
      local q1, _, cap = capture_angles(2, 3, roll, false, gate)
      local d = 0
      for _, n in ipairs({ 'l_ank_roll', 'r_ank_roll', 'l_hip_roll', 'r_hip_roll' }) do
        d = d + math.abs(q1[ji[n]] - q0[ji[n]])
      end
      return d, cap.err[2], cap.gate[2]
    end
    local h = params.tZmp * params.tZmp * G
    local db = params.stepAdjust.deadband[2]
    -- an error beyond the dead band but below activateFrom: nothing; without the gate: the terms
    local roll = math.asin((db + 0.005) / h)
    local d, e, g = change(roll, db + 0.01, db + 0.03)
    assert.is_true(e > db and e < db + 0.01)
    assert.are.equal(0, g)
    assert.are.equal(0, d)
    local d_on, _, g_on = change(roll, 0, 0)
    assert.are.equal(1, g_on)
    assert.is_true(d_on > 0.005)
    -- half way between activateFrom and activateFull: half the terms
    local half = change(roll, e - 0.001, e + 0.001)
    assert.is_near(0.5 * d_on, half, 1e-9)
  end)

  it('holds the activation for activateHold after the error reached activateFull, fading', function()
    local w, p, cap = walk(0)
    p.stepAdjust.activateFrom, p.stepAdjust.activateFull = { 0, 0.03 }, { 0, 0.05 }
    local h = p.tZmp * p.tZmp * G
    local big, small = -math.asin(0.06 / h), -math.asin(0.01 / h) -- errors of 0.06 and 0.01 m
    -- without a hold the gate follows the error at once
    p.stepAdjust.activateHold = 0
    cap:sense(w, sensors(p, 0, 0, big), { 0, 0, 0 }, dt)
    assert.are.equal(1, cap.gate[2])
    cap:sense(w, sensors(p, 0, 0, small), { 0, 0, 0 }, dt)
    assert.are.equal(0, cap.gate[2])
    -- with a hold of 0.5 s: 1 - t / 0.5 after the push's error, 0 from then on
    p.stepAdjust.activateHold = 0.5
    cap:sense(w, sensors(p, 0, 0, big), { 0, 0, 0 }, dt)
    local n = math.floor(0.25 / dt + 0.5)
    for _ = 1, n do cap:sense(w, sensors(p, 0, 0, small), { 0, 0, 0 }, dt) end
    assert.is_near(1 - n * dt / 0.5, cap.gate[2], 1e-9)
    for _ = 1, n + 2 do cap:sense(w, sensors(p, 0, 0, small), { 0, 0, 0 }, dt) end
    assert.are.equal(0, cap.gate[2])
    assert.are.equal(1, cap.gate[1]) -- x: activateFull 0, no gate
  end)

  it('rests while the walk stands', function()
    local w, p, cap = walk(0.6)
    for _ = 1, 50 do cap:sense(w, sensors(p, 0, 3), { 0, 0, 0 }, dt) end
    assert.are.equal(0, cap.err[2])
  end)
end)
