-- luacheck: std +busted
-- Stepping around another robot (Player/BodyFSM/nav.lua avoid): the way clear, a robot in the way
-- (passed on the side away from it, the side kept), one beside the path, behind, or past the target.
local nav = require('BodyFSM.nav')
local Config = require('Config')

local body = Config.load('behavior', nil, { robot = 'op3', platform = 'Sim' }).body

local function ctx_with(obstacles)
  return { cfg = { body = body }, world = { obstacles = obstacles } }
end

describe('nav avoid', function()
  it('goes straight when nothing is in the way', function()
    local ctx = ctx_with({ { x = -1.0, y = 0 }, { x = 1.0, y = 1.5 }, { x = 3.5, y = 0 } })
    local wx, wy = nav.avoid(ctx, 3.0, 0)
    assert.are.equal(3.0, wx)
    assert.are.equal(0, wy)
    assert.is_nil(ctx.avoid_side)
  end)

  it('steers past a robot in the way on the side away from it, and keeps that side', function()
    local ctx = ctx_with({ { x = 1.0, y = 0.1 } }) -- a little left of the path: pass on its right
    local wx, wy = nav.avoid(ctx, 3.0, 0)
    assert.is_true(wy < 0, 'waypoint ' .. wx .. ', ' .. wy)
    assert.is_true(wx > 0)
    -- the clearance: the waypoint's direction passes the robot at least `clearance` away
    local th = math.atan2(wy, wx)
    local d = math.abs(math.sin(th - math.atan2(0.1, 1.0))) * math.sqrt(1.01)
    assert.is_true(d >= body.nav.avoid.clearance - 1e-9, 'passes at ' .. d)
    -- it moved to the other side of the path: the side chosen is kept
    ctx.world.obstacles[1].y = -0.1
    local _, wy2 = nav.avoid(ctx, 3.0, 0)
    assert.is_true(wy2 < 0)
  end)

  it('goes straight in the last steps to the target', function()
    local ctx = ctx_with({ { x = 0.2, y = 0 } })
    local wx, wy = nav.avoid(ctx, 0.4, 0)
    assert.are.equal(0.4, wx)
    assert.are.equal(0, wy)
  end)

  it('walks the target distance, not the waypoint\'s, in go_to', function()
    local ctx = ctx_with({ { x = 1.0, y = 0 } })
    local vx, vy, va, d = nav.go_to(ctx, 3.0, 0, 0)
    assert.are.equal(3.0, d)
    assert.is_true(va ~= 0 or vy ~= 0, 'turns or side-steps away')
    assert.is_true(vx >= 0)
  end)
end)
