-- luacheck: std +busted
-- Stepping around another robot (Player/BodyFSM/nav.lua avoid): the way clear, a robot in the way
-- (passed on the side away from it, the side kept), one beside the path, behind, or past the target;
-- teammates from their messages; the dribble's detour round a robot ahead of the ball.
local nav = require('BodyFSM.nav')
local dribble = require('BodyFSM.dribble')
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

  -- a world at the field's origin facing +x (robot frame = field frame), with teammates heard
  local function with_mates(mates, localised)
    local ctx = ctx_with({})
    ctx.world.mates = mates
    ctx.world.localised = function() return localised end
    ctx.world.to_robot = function(_, fx, fy) return fx, fy end
    return ctx
  end
  local function mate(x, y, age) return { pose = { x, y, 0 }, age = age or 0.2, penalised = false } end

  it('steps around a teammate in the way that it knows from its messages, once its own pose is trusted', function()
    local ctx = with_mates({ mate(1.0, 0.1) }, true)
    local wx, wy = nav.avoid(ctx, 3.0, 0)
    assert.is_true(wy < 0 and wx > 0, 'waypoint ' .. wx .. ', ' .. wy)
    -- an old message, a penalised teammate, or our pose not trusted: not an obstacle
    for _, c in ipairs({ with_mates({ mate(1.0, 0.1, body.nav.avoid.mate_age + 0.1) }, true),
      with_mates({ mate(1.0, 0.1) }, false) }) do
      wx, wy = nav.avoid(c, 3.0, 0)
      assert.are.equal(3.0, wx)
      assert.are.equal(0, wy)
    end
    local pen = mate(1.0, 0.1)
    pen.penalised = true
    assert.are.equal(0, select(2, nav.avoid(with_mates({ pen }, true), 3.0, 0)))
  end)

  it('dribbling: the aim turns away from a robot in the lane ahead of the ball, enough to clear it', function()
    local d = body.dribble
    local ctx = ctx_with({ { x = 0.9, y = 0.2 } }) -- ahead, a little left of the ball's line
    local turn = dribble.detour(ctx, 0.2, 0, 1, 0)
    assert.is_true(turn < 0 and turn >= -d.avoid_angle, 'turn ' .. turn)
    assert.is_true(math.abs(turn - -math.atan2(d.avoid_lane - 0.2, 0.7)) < 1e-9)
    -- the side is kept while the robot is in the lane
    ctx.world.obstacles[1].y = -0.05
    assert.is_true(dribble.detour(ctx, 0.2, 0, 1, 0) < 0)
    -- out of the lane, behind the ball, or beyond the look-ahead: straight on, and the side forgotten
    for _, o in ipairs({ { x = 0.9, y = 0.6 }, { x = 0.1, y = 0 }, { x = 0.2 + d.avoid_ahead + 0.1, y = 0 } }) do
      ctx.world.obstacles[1] = o
      assert.are.equal(0, dribble.detour(ctx, 0.2, 0, 1, 0))
      assert.is_nil(ctx.dribble_side)
    end
  end)
end)
