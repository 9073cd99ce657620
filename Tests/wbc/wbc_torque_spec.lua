-- luacheck: std +busted
-- Operational-space torque control of a limb (Lib/wbc_torque.lua over Modules/wbc's wbc_solve_torque)
-- in the model alone: the Hubo2+'s right arm, the rest of the body fixed, integrated with the same
-- rigid-body model (A qdd = tau - h). With no target and no gains the torques are the gravity and
-- Coriolis terms; holding a target, the hand stays; a 0.1 m circle at 0.5 Hz is tracked within 1 mm
-- RMS; a constant force on the hand moves it by (1/kp) J A^-1 J^T f (the stiffness kp Lambda); every
-- torque is within the actuators' limits; bad input is refused naming it; the skill's torque keys
-- are checked (Config/spec/wbc.lua).
local wbc_torque = require('wbc_torque')
local dynamics = require('dynamics')
local Config = require('Config')

local ARM = { 'RSP', 'RSR', 'RSY', 'REB', 'RWY', 'RWP' }
local RAISED = { -0.7, 0.26, 0, -1.0, 0, 0 }
local BASE = { 0, 0, 0.75, 0, 0, 0 }
local DT, CTL = 0.001, 5   -- the model's step (s) and the control period in steps (200 Hz)

-- The arm's joints' indices in robot order, a state with the arm raised, the plant's model.
local function setup()
  local m = dynamics.load({ robot = 'hubo2plus' })
  local idx, q, qd = {}, {}, {}
  for i = 1, m.n do q[i], qd[i] = 0, 0 end
  for k, name in ipairs(ARM) do
    for i, j in ipairs(m.joints) do if j == name then idx[k] = i end end
    q[idx[k]] = RAISED[k]
  end
  return m, idx, q, qd
end

-- The arm's acceleration from A qdd = tau + J^T f - h (the other joints and the base fixed).
local function accelerate(m, idx, q, qd, tau, f)
  local v = { 0, 0, 0, 0, 0, 0 }
  for i = 1, m.n do v[6 + i] = qd[i] end
  m:set(q, BASE, v)
  local M, h, J = m:mass_matrix(), m:nonlinear(), m:jacobian('r_palm')
  local n, a = #idx, {}
  for r = 1, n do
    a[r] = {}
    for c = 1, n do a[r][c] = M[6 + idx[r]][6 + idx[c]] end
    local ext = 0
    if f then for k = 1, 3 do ext = ext + J[k][6 + idx[r]] * f[k] end end
    a[r][n + 1] = tau[r] + ext - h[6 + idx[r]]
  end
  for col = 1, n do
    for r = 1, n do
      if r ~= col then
        local x = a[r][col] / a[col][col]
        for c = col, n + 1 do a[r][c] = a[r][c] - x * a[col][c] end
      end
    end
  end
  for k, i in ipairs(idx) do
    qd[i] = qd[i] + a[k][n + 1] / a[k][k] * DT
    q[i] = q[i] + qd[i] * DT
  end
end

local function palm(m, q)
  m:set(q, BASE)
  local p = m:pose('r_palm')
  return { p[1], p[2], p[3] }
end

local GAINS = { kp = 400, kd = 40, posture_kp = 100, posture_kd = 20, damping = 100 }

-- Runs `seconds` of the closed loop; target(t) gives position, velocity, acceleration (or nil);
-- each(t, c) after every control step. Returns the worst |tau| / limit.
local function run(seconds, target, f, each)
  local m, idx, q, qd = setup()
  local c = wbc_torque.new({ robot = 'hubo2plus', joints = ARM, frame = 'r_palm', dt = DT * CTL })
  local posture = {}
  for k, i in ipairs(idx) do posture[k] = q[i] end
  local p0 = palm(m, q)
  local tau, worst = {}, 0
  for s = 0, math.floor(seconds / DT + 0.5) do
    if s % CTL == 0 then
      local t = s * DT
      if target then c:target(target(t, p0)) end
      tau = c:torques(q, qd, BASE, GAINS, posture)
      for k = 1, #tau do worst = math.max(worst, math.abs(tau[k]) / c.limit[k]) end
      if each then each(t, c, m, q, p0) end
    end
    accelerate(m, idx, q, qd, tau, f)
  end
  return worst, m, q, p0, c
end

describe('wbc_torque', function()
  it('with no target and no gains gives the gravity and Coriolis terms', function()
    local m, idx, q, qd = setup()
    local c = wbc_torque.new({ robot = 'hubo2plus', joints = ARM, frame = 'r_palm' })
    for k, i in ipairs(idx) do qd[i] = 0.1 * k end
    local tau = c:torques(q, qd, BASE, { kp = 0, kd = 0 })
    local v = { 0, 0, 0, 0, 0, 0 }
    for i = 1, m.n do v[6 + i] = qd[i] end
    m:set(q, BASE, v)
    local h = m:nonlinear()
    for k, i in ipairs(idx) do assert.is_true(math.abs(tau[k] - h[6 + i]) < 1e-9, ARM[k]) end
  end)

  it('holds a target and tracks a 0.1 m circle at 0.5 Hz within 1 mm RMS', function()
    local w, r = math.pi, 0.05
    local sum2, count = 0, 0
    local worst = run(4, function(t, p0)
      local cs, sn = math.cos(w * t), math.sin(w * t)
      return { p0[1], p0[2] + r * (cs - 1), p0[3] + r * sn }, { 0, -r * w * sn, r * w * cs },
        { 0, -r * w * w * cs, -r * w * w * sn }
    end, nil, function(t, c)
      if t >= 2 then sum2, count = sum2 + c:status().error ^ 2, count + 1 end
    end)
    local rms = math.sqrt(sum2 / count)
    assert.is_true(rms < 1e-3, string.format('RMS %.2f mm', rms * 1e3))
    assert.is_true(worst <= 1, 'torques within the limits')
    local _, m, q, p0 = run(1, function(_, p) return p end)
    local p = palm(m, q)
    local e = math.sqrt((p[1] - p0[1]) ^ 2 + (p[2] - p0[2]) ^ 2 + (p[3] - p0[3]) ^ 2)
    assert.is_true(e < 1e-4, string.format('held within %.3f mm', e * 1e3))
  end)

  it('yields to a force on the hand by (1/kp) J A^-1 J^T f', function()
    local f = { -20, 0, 0 }
    local _, m, q, p0, c = run(3, function(_, p) return p end, f)
    local C = c:compliance()
    local p = palm(m, q)
    for r = 1, 3 do
      local expect = (C[r][1] * f[1] + C[r][2] * f[2] + C[r][3] * f[3]) / GAINS.kp
      assert.is_true(math.abs((p[r] - p0[r]) - expect) < 0.05 * math.abs(expect) + 2e-4,
        string.format('axis %d: moved %.2f mm, expected %.2f mm', r, (p[r] - p0[r]) * 1e3, expect * 1e3))
    end
  end)

  it('refuses bad input, naming it', function()
    local function refuses(pattern, fn)
      local ok, err = pcall(fn)
      assert.is_false(ok)
      assert.is_truthy(tostring(err):find(pattern, 1, true), tostring(err))
    end
    refuses("'RXX'", function() wbc_torque.new({ robot = 'hubo2plus', joints = { 'RXX' }, frame = 'r_palm' }) end)
    refuses("'nowhere'", function() wbc_torque.new({ robot = 'hubo2plus', joints = ARM, frame = 'nowhere' }) end)
    local c = wbc_torque.new({ robot = 'hubo2plus', joints = ARM, frame = 'r_palm' })
    refuses('position[2]', function() c:target({ 0, 0 / 0, 0 }) end)
    refuses('velocity', function() c:target({ 0, 0, 0 }, { 0, 0 }) end)
    local _, _, q, qd = setup()
    q[3] = math.huge
    refuses('not finite', function() c:torques(q, qd, BASE, GAINS) end)
  end)

  it("the skill's torque keys are checked", function()
    local spec = dofile(os.getenv('HRP_ROOT') .. '/Config/spec/wbc.lua')
    local cfg = Config.load('wbc', nil, { robot = 'hubo2plus' }).torque
    assert.is_true(spec.torque(cfg))
    local bad = {}
    for k, v in pairs(cfg) do bad[k] = v end
    bad.kp = -1
    local msg, key = spec.torque(bad)
    assert.are.equal('kp', key)
    assert.is_truthy(msg)
    bad.kp, bad.enabled = 400, 'yes'
    assert.are.equal('enabled', select(2, spec.torque(bad)))
  end)
end)
