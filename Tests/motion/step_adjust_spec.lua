-- luacheck: std +busted
-- The step adjustment (Player/Motion/step_adjust.lua) on the walk generator alone: a capture point
-- error (as the IMU would give it) moves the landing, chooses the swing foot, puts a swing foot down.
local Walk = require('Motion.walk')
local capture = require('Motion.capture')
local step_adjust = require('Motion.step_adjust')
local fixture = require('Tests.motion.walk_fixture')

local params, model, dt, copy = fixture.params, fixture.model, fixture.dt, fixture.copy

-- a walk at 0.2 m/s with the step adjustment on, advanced until a step with `swing_left` begins
local function walking(swing_left, sa)
  local p = copy(params)
  -- over the body's (the keys not named here keep their defaults: Config/common/walk.lua)
  for k, v in pairs({ gain = 1, deadband = { 0.02, 0.02 }, max = { 0.05, 0.08 }, switchError = 0.045,
    touchdownError = 0.06, touchdownTime = 0.05, level = { 0, 0 }, levelTime = 0.15 }) do p.stepAdjust[k] = v end
  for k, v in pairs(sa or {}) do p.stepAdjust[k] = v end
  local w = Walk.new(p, model)
  -- the capture estimate's error, set by the tests (no IMU here)
  local cap = capture.new()
  cap.err = { 0, 0 }
  w:extend(step_adjust.new(cap))
  w:set_velocity(0.2, 0, 0)
  w:start()
  for _ = 1, 400 do
    w:advance(dt)
    if w.stats.steps >= 4 and w.t < dt / 2 and (w.support == Walk.RIGHT) == swing_left then return w, p, cap end
  end
  error('no step began')
end

local function rel_y(w, left)
  local a, b = w.uLeft2, w.uRight2
  local r = Walk.pose_relative(left and a or b, left and b or a)
  return r[2]
end

describe('step adjustment', function()
  it('lands the swing foot further out by gain x the error beyond the dead band, within the step limit', function()
    local w, p, cap = walking(true)
    local nominal = rel_y(w, true)
    cap.err[2] = 0.05 -- pushed left while the left foot swings
    for _ = 1, 10 do w:advance(dt) end
    assert.is_near(nominal + 0.03, rel_y(w, true), 1e-6)
    cap.err[2] = 0.5
    for _ = 1, 2 do w:advance(dt) end
    assert.is_near(p.stepLimitY[2], rel_y(w, true), 1e-6)
  end)

  it('keeps the landing nominal while the activation is 0 (the errors of normal walking)', function()
    local w, _, cap = walking(true)
    local nominal = rel_y(w, true)
    cap.err[2], cap.gate = 0.05, { 1, 0 }
    for _ = 1, 10 do w:advance(dt) end
    assert.is_near(nominal, rel_y(w, true), 1e-9)
    -- half on: half the move
    cap.gate[2] = 0.5
    for _ = 1, 2 do w:advance(dt) end
    assert.is_near(nominal + 0.015, rel_y(w, true), 1e-6)
  end)

  it('moves the landing without a jump of the swing foot', function()
    local w, _, cap = walking(true)
    for _ = 1, 10 do w:advance(dt) end
    local y0 = w.uLeft[2]
    cap.err[2] = 0.06
    w:advance(dt)
    -- one tick of the swing, not the 4 cm of the new landing
    assert.is_true(math.abs(w.uLeft[2] - y0) < 0.01)
  end)

  it('swings the foot on the side of the push at a step start, even twice in a row', function()
    local w, _, cap = walking(false) -- the right foot swings now; the left would be next
    cap.err[2] = -0.06       -- pushed right: the right foot must swing again
    for _ = 1, 40 do
      w:advance(dt)
      if w.t < dt / 2 then break end
    end
    assert.are.equal(Walk.LEFT, w.support)
    assert.is_true((w.stats.switched or 0) >= 1)
  end)

  it('puts a swing foot on the far side of the push down where it is and ends the step early', function()
    local w, _, cap = walking(false) -- the right foot swings
    for _ = 1, 10 do w:advance(dt) end
    local steps = w.stats.steps
    cap.err[2] = 0.08        -- pushed left: the right foot cannot catch it
    w:advance(dt)
    assert.is_truthy(w.step.t_end)
    local landed = { w.uRight[1], w.uRight[2] }
    local ticks = 0
    repeat w:advance(dt) ticks = ticks + 1 until w.stats.steps > steps or ticks > 40
    assert.is_true(ticks * dt <= 0.05 + dt)
    assert.is_near(landed[1], w.uRight[1], 1e-3)
    assert.is_near(landed[2], w.uRight[2], 1e-3)
    -- and the step that begins swings the left foot
    assert.are.equal(Walk.RIGHT, w.support)
  end)

  it('does nothing with gain 0', function()
    local w, _, cap = walking(true, { gain = 0 })
    local nominal = rel_y(w, true)
    cap.err[2] = 0.1
    for _ = 1, 30 do w:advance(dt) end
    assert.is_near(nominal, rel_y(w, true), 1e-9)
    assert.is_nil(w.stats.adjusted)
  end)
end)
