-- luacheck: std +busted
-- The preview walk engine (Player/Motion/walk_preview.lua) without a robot: chosen by the walk
-- config, the same footsteps as the analytic engine, a COM whose velocity stays continuous across
-- steps, a ZMP that stays under the support foot, and a clean stop.
local control = require('Motion.control')
local fixture = require('Tests.motion.walk_fixture')

local robot, model, dt = fixture.robot, fixture.model, fixture.dt

local function params_for(engine)
  local p = fixture.copy(fixture.params)
  p.engine = engine
  return p
end

-- walks at (vx, vy, va) for `seconds`, then stops; returns a trace per tick
local function run(engine, vx, vy, va, seconds)
  local p = params_for(engine)
  local w = control.walk_engine(p).new(p, model):bind(robot)
  local q = {}
  for i = 1, #robot.joints do q[i] = 0 end
  w:set_velocity(vx, vy, va)
  w:start()
  local trace = {}
  for k = 1, math.floor((seconds + 3) / dt) do
    if k == math.floor(seconds / dt) then w:stop() end
    w:advance(dt)
    w:joint_angles(q, nil, dt)
    w:update_com_offset(q)
    trace[#trace + 1] = { com = { w.com[1], w.com[2] }, comd = { w.comd[1], w.comd[2] }, zmp = { w.zmp[1], w.zmp[2] },
      active = w.active, ss = w:single_support(), support = w.support, l = { unpack(w.uLeft) },
      r = { unpack(w.uRight) }, steps = w.stats.steps }
  end
  return w, trace
end

describe('preview walk engine', function()
  it('is chosen by the walk config, and a wrong name is refused with the key named', function()
    assert.are.equal(require('Motion.walk_preview'), control.walk_engine(params_for('preview')))
    assert.are.equal(require('Motion.walk'), control.walk_engine(params_for('analytic')))
    local ok, err = pcall(control.walk_engine, params_for('fast'), 'Config/robots/op3/walk.lua')
    assert.is_false(ok)
    assert.matches("walk.lua: key 'engine' must be 'analytic' or 'preview', got 'fast'", err, 1, true)
  end)

  it('turns fast in the shorter steps of turnStep, whole ticks each, with the same footsteps', function()
    local function steps_of(engine)
      local w, trace = run(engine, 0, 0, 2.0, 5)
      local n, last = 0, trace[math.floor(3 / dt)].steps
      for k = math.floor(3 / dt) + 1, math.floor(4 / dt) do
        if trace[k].steps ~= last then n, last = n + 1, trace[k].steps end
      end
      return n, w
    end
    local p = fixture.params
    local T = p.turnStep and p.turnStep.tStep or p.tStep
    local n, w = steps_of('preview')
    assert.is_near(1 / (math.floor(T / dt + 0.5) * dt), n, 1)
    assert.is_near(math.floor(T / dt + 0.5) * dt, w:step_time({ 0, 0, 2.0 }), 1e-12)
    assert.are.equal(steps_of('analytic'), n)
  end)

  it('keeps the COM velocity continuous where the analytic engine jumps at step boundaries', function()
    local function worst_jump(engine)
      local _, trace = run(engine, 0.3, 0, 0, 4)
      local worst = 0
      for k = 2, #trace do
        if trace[k].active and trace[k - 1].active and trace[k].steps > 2 then
          for a = 1, 2 do worst = math.max(worst, math.abs(trace[k].comd[a] - trace[k - 1].comd[a])) end
        end
      end
      return worst
    end
    local analytic, prev = worst_jump('analytic'), worst_jump('preview')
    -- an acceleration of at most ~1.2 g between two ticks
    assert.is_true(prev < 12 * dt, string.format('preview: COM velocity changes by %.3f m/s in a tick', prev))
    assert.is_true(prev < analytic, string.format('preview %.3f < analytic %.3f m/s', prev, analytic))
  end)

  it('keeps the planned ZMP under the support foot in single support while the command holds', function()
    local _, trace = run('preview', 0.25, 0.05, 0.3, 5)
    local p = fixture.params
    local worst = 0
    for k, s in ipairs(trace) do
      -- until the stop: a stop is not foreseen, and the step after it departs from the plan
      if k * dt < 5 and s.active and s.ss == 1 and s.steps > 1 then
        local foot = s.support == 0 and s.l or s.r
        local c, sn = math.cos(foot[3]), math.sin(foot[3])
        local dx, dy = s.zmp[1] - foot[1], s.zmp[2] - foot[2]
        local fx, fy = c * dx + sn * dy - p.supportX, -sn * dx + c * dy
        worst = math.max(worst, math.sqrt(fx * fx + fy * fy))
      end
    end
    -- the planned ZMP, not the reference: the controller trades a little error for a smooth COM
    assert.is_true(worst < 0.01, string.format('ZMP %.4f m from the support point', worst))
  end)

  it('stops with the feet together and comes to rest into stance without a jump', function()
    local w, trace = run('preview', 0.2, 0, 0.2, 3)
    assert.is_false(w.active)
    assert.is_true(w:feet_together())
    local jump, rest = 0, trace[#trace]
    for k = 2, #trace do
      local a, b = trace[k].com, trace[k - 1].com
      jump = math.max(jump, math.abs(a[1] - b[1]), math.abs(a[2] - b[2]))
    end
    -- the stop is planned when it is asked, not a step later: the ZMP never runs ahead of the front
    -- foot (replanned only at the next step, it spiked 3 cm ahead)
    local ahead = 0
    for _, s in ipairs(trace) do
      -- along the heading (the walk turns): the ZMP against the front foot's ankle point
      local h = 0.5 * (s.l[3] + s.r[3])
      local function along(x, y) return x * math.cos(h) + y * math.sin(h) end
      ahead = math.max(ahead, along(s.zmp[1], s.zmp[2]) - math.max(along(s.l[1], s.l[2]), along(s.r[1], s.r[2])))
    end
    assert.is_true(ahead < 0.01, string.format('the ZMP %.4f m ahead of the front foot', ahead))
    -- at most what 0.4 m/s moves the COM in a tick
    assert.is_true(jump < 0.4 * dt, string.format('the COM moves %.4f m in a tick', jump))
    local mid = { 0.5 * (rest.l[1] + rest.r[1]), 0.5 * (rest.l[2] + rest.r[2]) }
    assert.is_near(mid[1], rest.com[1], 1e-3)
    assert.is_near(mid[2], rest.com[2], 1e-3)
  end)
end)
