-- luacheck: std +busted
-- When the body machine shoots with a kick out of the walk (Player/BodyFSM/shot.lua): the ball in
-- the kick zone ahead of one foot, the goal in front and near enough, the pose trusted, the walk
-- going straight; the foot on the ball's side.
local Config = require('Config')
local shot = require('BodyFSM.shot')

local cfg = Config.load('behavior')

local function copy(t)
  local c = {}
  for k, v in pairs(t) do c[k] = type(v) == 'table' and copy(v) or v end
  return c
end

-- a robot at field pose (x, y, a) with the ball at (bx, by) in its frame, walking at (vy, va)
local function ctx(x, y, a, bx, by, opts)
  opts = opts or {}
  local body = copy(cfg.body)
  body.walk_kick.enabled = true
  body.walk_kick.max_range = opts.range or 6.0
  local world = {
    cfg = { field = cfg.world.field }, pose = { x = x, y = y, a = a, confidence = opts.confidence or 0.9 },
    ball = { x = bx, y = by, t_seen = 10 }, t = 10.1,
  }
  function world.ball_known() return true end
  function world.ball_age(w) return w.t - w.ball.t_seen end
  function world.to_robot(w, fx, fy)
    local p = w.pose
    local dx, dy = fx - p.x, fy - p.y
    local c, s = math.cos(-p.a), math.sin(-p.a)
    return c * dx - s * dy, s * dx + c * dy
  end
  function world.ball_field(w)
    local p = w.pose
    local c, s = math.cos(p.a), math.sin(p.a)
    return p.x + c * w.ball.x - s * w.ball.y, p.y + s * w.ball.x + c * w.ball.y
  end
  return { cfg = { body = body }, world = world, t = 10.1,
    act = { walk_velocity = function() return 0.1, opts.vy or 0, opts.va or 0 end } }
end

describe('shot.foot', function()
  it('shoots with the foot on the ball\'s side when the goal is in front', function()
    assert.equal('left', shot.foot(ctx(2.0, 0, 0, 0.2, 0.06)))
    assert.equal('right', shot.foot(ctx(2.0, 0, 0, 0.2, -0.06)))
  end)

  it('holds off with the ball out of the zone, centred, or the goal off to the side or too far', function()
    local wk = cfg.body.walk_kick
    local far = wk.x[2] + wk.x_far
    assert.is_nil(shot.foot(ctx(2.0, 0, 0, far + 0.02, 0.06)))   -- too far ahead
    assert.equal('left', shot.foot(ctx(2.0, 0, 0, far - 0.01, 0.06))) -- beyond the zone, the walk waits for a step
    assert.is_nil(shot.foot(ctx(2.0, 0, 0, wk.x[1] - 0.01, 0.06))) -- too near
    assert.is_nil(shot.foot(ctx(2.0, 0, 0, 0.2, 0.0)))           -- between the feet
    assert.is_nil(shot.foot(ctx(2.0, 0, 0, 0.2, 0.2)))           -- beside the robot
    assert.is_nil(shot.foot(ctx(2.0, 0, 0.8, 0.2, 0.06)))        -- facing away from the goal
    assert.is_nil(shot.foot(ctx(2.0, 2.5, 0, 0.2, 0.06)))        -- the goal's mouth off to the side
    -- near the line, off to the side: the goal's centre within max_angle of the heading, but the
    -- heading's line from the ball passes the post (the mouth seen at an angle)
    assert.is_nil(shot.foot(ctx(4.0, 1.8, -0.9, 0.2, 0.06)))
    assert.equal('left', shot.foot(ctx(4.0, 1.2, -0.9, 0.2, 0.06))) -- ... and inside it
    assert.is_nil(shot.foot(ctx(-3.0, 0, 0, 0.2, 0.06, { range = 2.5 }))) -- out of range
  end)

  it('holds off while turning or side-stepping, or when the pose is not trusted', function()
    local wk = cfg.body.walk_kick
    assert.is_nil(shot.foot(ctx(2.0, 0, 0, 0.2, 0.06, { va = wk.max_va + 0.05 })))
    assert.is_nil(shot.foot(ctx(2.0, 0, 0, 0.2, 0.06, { vy = wk.max_vy + 0.02 })))
    assert.equal('left', shot.foot(ctx(2.0, 0, 0, 0.2, 0.06, { vy = wk.max_vy - 0.01, va = wk.max_va - 0.05 })))
    assert.is_nil(shot.foot(ctx(2.0, 0, 0, 0.2, 0.06, { confidence = 0.1 })))
  end)
end)
