-- luacheck: std +busted
-- The balance feedback (Player/Motion/balance.lua) without a robot: the ZMP from the feet's
-- wrenches, the direction and bound of the COM shift, no feedback without contact, the stability
-- cap of the gain (a bad `balance` config: Tests/motion/walk_config_spec.lua).
local balance = require('Motion.balance')

local function params(over)
  local b = { zmpGain = { 2, 2 }, walkGain = { 1, 0 }, leakTime = 2, maxShift = 0.03, maxRate = 1,
    filterTime = 0.3,    walkFilterTime = 1,    minForce = 40, sensorHeight = 0.1 }
  for k, v in pairs(over or {}) do b[k] = v end
  return { tZmp = 0.26, balance = b }
end

-- ft of both feet: each { fx, fy, fz, mx, my }
local function wrench(l, r)
  local ft = {}
  for k = 1, 24 do ft[k] = 0 end
  for i = 1, 5 do ft[i], ft[6 + i] = l[i], r[i] end
  return ft
end
local LEFT, RIGHT = { 0, 0.1, 0 }, { 0, -0.1, 0 }

describe('balance', function()
  it('measures the ZMP of both feet from their wrenches (sensor height and horizontal forces)', function()
    local b = balance.new(params())
    -- left foot: 200 N pressing 2 cm ahead of its ankle (my = -px fz); right foot: 200 N, 1 cm
    -- inward (mx = py fz, py = -... inward of the right foot is +y)
    assert.is_true(b:measure(wrench({ 0, 0, 200, 0, -4 }, { 0, 0, 200, 2, 0 }), LEFT, RIGHT))
    assert.is_near(0.01, b.zmp[1], 1e-12)
    assert.is_near(0.005, b.zmp[2], 1e-12)
    -- a horizontal force through the sole at the ankle gives a moment h * fx about the sensor
    assert.is_true(b:measure(wrench({ 20, 0, 200, 0, -20 * 0.1 }, { 0, 0, 0, 0, 0 }), LEFT, RIGHT))
    assert.is_near(0, b.zmp[1], 1e-12)
    assert.is_near(0.1, b.zmp[2], 1e-12)
    -- a turned foot: its pressure point turns with it
    assert.is_true(b:measure(wrench({ 0, 0, 0, 0, 0 }, { 0, 0, 100, 0, -3 }), LEFT, { 0, -0.1, math.pi / 2 }))
    assert.is_near(0, b.zmp[1], 1e-12)
    assert.is_near(-0.07, b.zmp[2], 1e-12)
  end)

  it('measures the ZMP on point pressure sensors (robot.lua foot_pressure) when the body has them', function()
    -- a rectangle of four sensors per foot, 0.08 x 0.04 m, centred 0.01 m ahead of the sole frame
    local pts = { { 0.05, -0.02 }, { 0.05, 0.02 }, { -0.03, -0.02 }, { -0.03, 0.02 } }
    local robot = { foot_pressure = { lfoot = { frame = 'l_sole', points = pts },
      rfoot = { frame = 'r_sole', points = pts } } }
    -- one foot: the forces' weighted mean position, their sum
    local fz, x, y = balance.sole_cop(pts, { 10, 30, 10, 30 }, 0)
    assert.is_near(80, fz, 1e-12)
    assert.is_near(0.01, x, 1e-12)
    assert.is_near(0.01, y, 1e-12)
    fz, x, y = balance.sole_cop(pts, { 0, 0, 0, 0, 40, 0, 0, 0 }, 4)
    assert.is_near(40, fz, 1e-12)
    assert.is_near(0.05, x, 1e-12)
    assert.is_near(-0.02, y, 1e-12)
    assert.are.same({ 0, 0, 0 }, { balance.sole_cop(pts, { 0, 0, 0, 0 }, 0) })
    -- both feet: each foot's centre of pressure turned and moved with its pose, weighted by its force;
    -- the ankle F/T (ft) is not read
    local b = balance.new(params(), robot)
    local ft = wrench({ 0, 0, 500, 9, 9 }, { 0, 0, 500, 9, 9 })
    -- left: 100 N on its front sensors (x 0.05, y 0); right (turned 90 deg): 100 N on its rear
    -- sensors (x -0.03, y 0 in its frame: 0.03 towards -y in the ground frame)
    local press = { 50, 50, 0, 0, 0, 0, 50, 50 }
    assert.is_true(b:measure(ft, LEFT, { 0, -0.1, math.pi / 2 }, press))
    assert.is_near(100, b.force[1], 1e-12)
    assert.is_near(0.5 * 0.05 + 0.5 * 0, b.zmp[1], 1e-12)
    assert.is_near(0.5 * 0.1 + 0.5 * (-0.1 - 0.03), b.zmp[2], 1e-12)
    -- a foot under minForce does not count; none loaded: no contact
    assert.is_true(b:measure(ft, LEFT, RIGHT, { 15, 15, 15, 15, 0, 0, 20, 20 }))
    assert.is_near(0.01, b.zmp[1], 1e-12)
    assert.is_near(0.1, b.zmp[2], 1e-12)
    assert.is_false(b:measure(ft, LEFT, RIGHT, { 5, 5, 5, 5, 5, 5, 5, 5 }))
    -- the update reads them too
    b:update(0.005, ft, LEFT, RIGHT, { 0, 0 }, false, { 20, 20, 20, 20, 20, 20, 20, 20 })
    assert.is_true(b.contact)
    assert.is_near(0.01, b.err[1], 1e-12)
    assert.is_near(0, b.err[2], 1e-12)
  end)

  it('moves the COM against a lasting ZMP error, bounded, and leaks back when the error goes', function()
    local b = balance.new(params())
    local ft = wrench({ 0, 0, 200, 0, -0.03 * 200 }, { 0, 0, 200, 0, -0.03 * 200 }) -- ZMP 3 cm ahead
    for _ = 1, 200 do b:update(0.005, ft, LEFT, RIGHT, { 0, 0 }) end
    assert.is_true(b.contact)
    assert.is_near(0.03, b.err[1], 1e-12)
    assert.is_true(b.shift[1] < -0.005, 'shift back: ' .. b.shift[1])
    assert.is_near(0, b.shift[2], 1e-9)
    -- walking: the lateral gain is 0 (walkGain { 1, 0 }): a lateral error leaves y alone
    local side = balance.new(params())
    local ft_side = wrench({ 0, 0, 200, 0.02 * 200, 0 }, { 0, 0, 200, 0.02 * 200, 0 })
    for _ = 1, 200 do side:update(0.005, ft_side, LEFT, RIGHT, { 0, 0 }, true) end
    assert.is_near(0.02, side.err[2], 1e-12)
    assert.are.equal(0, side.shift[2])
    for _ = 1, 200 do side:update(0.005, ft_side, LEFT, RIGHT, { 0, 0 }, false) end
    assert.is_true(side.shift[2] < -0.001)
    for _ = 1, 4000 do b:update(0.005, ft, LEFT, RIGHT, { 0, 0 }) end
    assert.is_true(math.abs(b.shift[1]) <= 0.03 + 1e-12)
    local s = b.shift[1]
    -- feet in the air: nothing measured, the shift decays
    local air = wrench({ 0, 0, 10, 0, 0 }, { 0, 0, 10, 0, 0 })
    for _ = 1, 400 do b:update(0.005, air, LEFT, RIGHT, { 0, 0 }) end
    assert.is_false(b.contact)
    assert.is_true(math.abs(b.shift[1]) < 0.5 * math.abs(s))
  end)

  it('is off at zmpGain 0 but still measures the error', function()
    local b = balance.new(params({ zmpGain = { 0, 0 }, walkGain = { 0, 0 } }))
    local ft = wrench({ 0, 0, 200, 0, -6 }, { 0, 0, 200, 0, -6 })
    for _ = 1, 200 do b:update(0.005, ft, LEFT, RIGHT, { 0, 0 }) end
    assert.is_near(0.03, b.err[1], 1e-12)
    assert.are.equal(0, b.shift[1])
  end)

  it('caps the gain below the cart-table stability bound', function()
    -- a huge gain acts as 0.5 * filterTime / tZmp^2: one tick's shift is bounded by it
    local p = params({ zmpGain = { 1000, 1000 } })
    local b = balance.new(p)
    local ft = wrench({ 0, 0, 200, 0, -6 }, { 0, 0, 200, 0, -6 })
    b:update(0.005, ft, LEFT, RIGHT, { 0, 0 })
    local k = 0.5 * 0.3 / (0.26 * 0.26)
    local alpha = 0.005 / (0.005 + 0.3)
    assert.is_near(-k * alpha * 0.03 * 0.005, b.shift[1], 1e-12)
  end)
end)
