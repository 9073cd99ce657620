-- luacheck: std +busted
-- ZMP preview control (Player/Motion/preview.lua) without a robot: the Riccati solution, the gains'
-- shape, and the closed loop on the cart-table model tracking a footstep-like ZMP reference.
local preview = require('Motion.preview')

-- OP3-like numbers: an 8 ms motion tick, COM 0.25 m high, a 1.6 s preview window.
local dt, zc, g = 0.008, 0.25, 9.81
local N = math.floor(1.6 / dt + 0.5)
local sys = preview.model(dt, zc, g)
local gains = preview.gains(sys, 1, 1e-6, N)

-- A ZMP reference that steps from foot to foot: 0 for 1 s, then +-0.04 m alternating every 0.4 s,
-- then back to 0 at 5 s. Built on sample indices: a reference from float times (t + j dt) can put one
-- sample on either side of a step on successive ticks, and the preview gains amplify that flicker
-- into ~2 cm of ZMP error.
local k_first, k_end, k_step = math.floor(1 / dt + 0.5), math.floor(5 / dt + 0.5), math.floor(0.4 / dt + 0.5)
local function pref_k(k)
  if k < k_first or k >= k_end then return 0 end
  return (math.floor((k - k_first) / k_step) % 2 == 0) and 0.04 or -0.04
end

local function run(seconds, ctl)
  local steps = math.floor(seconds / dt + 0.5)
  local trace = {}
  for k = 0, steps - 1 do
    local c, cd, cdd, p = ctl:step(function(j) return pref_k(k + j) end)
    trace[#trace + 1] = { t = (k + 1) * dt, k = k + 1, c = c, cd = cd, cdd = cdd, p = p, ref = pref_k(k + 1) }
  end
  return trace
end

describe('ZMP preview control', function()
  it('solves the Riccati equation of the augmented system', function()
    local P = gains.P
    for r = 1, 4 do for c = 1, 4 do
      assert.is_true(math.abs(P[r][c] - P[c][r]) <= 1e-9 * math.abs(P[1][1]), 'P is symmetric')
    end end
    assert.is_true(P[1][1] > 0)
    assert.is_true(gains.Gi > 0, 'integral gain pushes against the ZMP error')
    assert.is_true(gains.iterations > 1)
  end)

  it('has preview gains that start at -Gi and fade over the window', function()
    assert.are.equal(-gains.Gi, gains.Gd[1])
    local peak = 0
    for j = 1, N do peak = math.max(peak, math.abs(gains.Gd[j])) end
    assert.is_true(math.abs(gains.Gd[N]) < 1e-3 * peak, 'the window is long enough: Gd(N) ~ 0')
    -- A gain ~0.5 s ahead still matters: the controller anticipates the next step.
    assert.is_true(math.abs(gains.Gd[math.floor(0.5 / dt)]) > 1e-3 * peak)
  end)

  it('tracks a stepping ZMP reference and moves the COM before the ZMP steps', function()
    local ctl = preview.controller(sys, gains, 0)
    local trace = run(7, ctl)
    local worst, moved_before = 0, false
    for _, s in ipairs(trace) do
      -- away from the instants the reference jumps, the ZMP stays close to it
      local phase = ((s.k - k_first) % k_step) * dt
      if s.k > k_first and s.k < k_end and phase > 0.1 and phase < 0.35 then
        worst = math.max(worst, math.abs(s.p - s.ref))
      end
      if s.t < 1 and s.c > 1e-3 then moved_before = true end
    end
    assert.is_true(worst < 0.005, string.format('ZMP error in the steps %.4f m', worst))
    assert.is_true(moved_before, 'the COM starts moving before the first step')
    local last = trace[#trace]
    assert.is_true(math.abs(last.c) < 1e-3 and math.abs(last.cd) < 1e-2, 'comes to rest over the final ZMP')
    -- the COM sways less than the ZMP: it stays between the feet
    for _, s in ipairs(trace) do assert.is_true(math.abs(s.c) < 0.04) end
  end)

  it('recovers from a disturbed state through its feedback', function()
    local ctl = preview.controller(sys, gains, 0)
    ctl:reset(0.02, 0.1, 0) -- 2 cm off and moving, reference 0
    local ref0 = function() return 0 end
    local c, cd
    for _ = 1, math.floor(3 / dt) do c, cd = ctl:step(ref0) end
    assert.is_true(math.abs(c) < 1e-3 and math.abs(cd) < 1e-2, string.format('settled at %.4f m', c))
  end)

  it('refuses weights that have no solution', function()
    assert.has_error(function() preview.gains(sys, 0, 1e-6, N) end)
    assert.has_error(function() preview.gains(sys, 1, 1e-6, 0) end)
  end)
end)
