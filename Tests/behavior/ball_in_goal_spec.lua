-- luacheck: std +busted
-- A scored ball is not followed into the net (Player/BodyFSM/nav.lua ball_in_goal, BodyFSM/wait.lua): the
-- ball's estimate beyond either goal line by body.ball_in_goal between the posts, trusted only with the
-- pose; the body states that walk to the ball hand over to wait, which stands until the ball is out.
local nav = require('BodyFSM.nav')
local wait = require('BodyFSM.wait')
local approach = require('BodyFSM.approach')
local machine = require('BodyFSM.machine')
local Config = require('Config')

local cfg = Config.load('behavior', nil, { robot = 'op3', platform = 'Sim' })

-- a robot at field (px, py) facing +x, the ball at field (bx, by)
local function ctx_at(px, py, bx, by, localised)
  local stops, walks = 0, 0
  local world = { cfg = cfg.world, pose = { x = px, y = py, a = 0, confidence = 1 },
    ball = { x = bx - px, y = by - py } }
  function world.localised() return localised ~= false end
  function world.ball_field(w) return w.pose.x + w.ball.x, w.pose.y + w.ball.y end
  function world.ball_known() return true end
  function world.ball_age() return 0 end
  local ctx = { cfg = cfg, world = world, t = 0,
    act = { stop = function() stops = stops + 1 end, walk = function() walks = walks + 1 end } }
  return ctx, function() return stops, walks end
end

describe('a ball in the goal', function()
  it('is beyond a goal line by ball_in_goal between the posts, either goal', function()
    local l, g = cfg.world.field.length / 2, cfg.body.ball_in_goal
    local m, post = g.beyond, cfg.world.field.goal_width / 2
    assert.is_true(nav.ball_in_goal((ctx_at(4.0, 0, l + m + 0.01, 0.5))))
    assert.is_true(nav.ball_in_goal((ctx_at(-4.0, 0, -(l + m + 0.01), -0.5))))
    assert.is_false(nav.ball_in_goal((ctx_at(4.0, 0, l + m - 0.01, 0))))      -- on the line: push it over
    assert.is_false(nav.ball_in_goal((ctx_at(4.0, 0, l + 0.3, post + 0.1))))  -- beside the goal, out
    assert.is_false(nav.ball_in_goal((ctx_at(4.0, 0, l + 0.3, post - g.inside + 0.01)))) -- at a post: play it
    assert.is_false(nav.ball_in_goal((ctx_at(4.0, 0, l + 0.3, 0, false))))    -- pose not trusted
  end)

  it('is waited for where the robot stands, and played again once out', function()
    local l = cfg.world.field.length / 2
    local ctx, counts = ctx_at(4.2, 0, l + 0.3, 0)
    assert.are.equal('in_goal', approach.update(ctx))
    assert.are.equal('wait', machine.transitions.approach.in_goal)
    assert.are.equal('wait', machine.transitions.align.in_goal)
    assert.are.equal('wait', machine.transitions.dribble.in_goal)
    wait.entry(ctx)
    assert.is_nil((wait.update(ctx)))
    local stops, walks = counts()
    assert.are.equal(2, stops)
    assert.are.equal(0, walks)
    ctx.world.ball = { x = -0.5, y = 0 }    -- thrown back in
    assert.are.equal('out', wait.update(ctx))
    assert.are.equal('approach', machine.transitions.wait.out)
    -- still in after `wait` s (a wrong pose): play on, and no waiting again for `retry` s
    local g = cfg.body.ball_in_goal
    ctx.world.ball = { x = 0.6, y = 0 }
    wait.entry(ctx)
    ctx.t = g.wait + 0.1
    assert.are.equal('out', wait.update(ctx))
    assert.is_false(nav.ball_in_goal(ctx))
    ctx.t = ctx.t + g.retry + 0.1
    assert.is_true(nav.ball_in_goal(ctx))
  end)
end)
