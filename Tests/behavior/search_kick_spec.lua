-- luacheck: std +busted
-- The search's look before it turns (Player/BodyFSM/search.lua with HeadFSM/scan.lua) and the walk
-- kick's closing on a ball that rolled on (Player/BodyFSM/kick.lua), on the OP3's behavior config.
local Config = require('Config')
local search = require('BodyFSM.search')
local scan = require('HeadFSM.scan')
local kick = require('BodyFSM.kick')
local track = require('HeadFSM.track')
local lookgoal = require('HeadFSM.lookgoal')

local cfg = Config.load('behavior', nil, { robot = 'op3', platform = 'Sim' })

-- a context at time t with the ball last seen `age` s ago at (bx, by) (robot frame)
local function context(t, bx, by, age, seen)
  local c = { cfg = cfg, t = t, walks = {}, heads = {} }
  c.world = { ball = { x = bx, y = by, seen = seen } }
  function c.world.ball_age() return age end
  function c.world.ball_known() return seen end
  c.act = {
    walk = function(vx, vy, va) c.walks[#c.walks + 1] = { vx, vy, va } end,
    head = function(pan, tilt) c.heads[#c.heads + 1] = { pan, tilt } end,
  }
  return c
end

describe('search', function()
  it('stands while the head sweeps its range once, then turns', function()
    local look = cfg.body.search_look_time
    assert.is_true(look >= cfg.head.scan_period / 2) -- the sweep across the range fits in the look
    local c = context(100, 0, 0, 50, false)
    search.entry(c)
    assert.equal(100, c.scan_restart)
    -- the head's scan, entered earlier, starts a sweep again at the look's start
    c.t = 90
    scan.entry(c)
    c.t = 100
    local pans = {}
    for k = 0, math.floor(look / 0.1) - 1 do
      c.t = 100 + k * 0.1
      assert.is_nil(search.update(c))
      local w = c.walks[#c.walks]
      assert.same({ 0, 0, 0 }, w)
      scan.update(c)
      pans[#pans + 1] = c.heads[#c.heads][1]
    end
    -- the head went from one end of its range to the other (pan about the robot's heading)
    local lo, hi = math.huge, -math.huge
    for _, p in ipairs(pans) do lo, hi = math.min(lo, p), math.max(hi, p) end
    local edge = cfg.head.scan_pan - 0.02 -- (the look-at's pan for the row's point at that bearing)
    assert.is_true(lo < -edge and hi > edge, string.format('pan %.3f .. %.3f', lo, hi))
    assert.is_true(pans[1] < -edge) -- from the far end, not mid-sweep
    c.t = 100 + look + 0.05
    search.update(c)
    local w = c.walks[#c.walks]
    assert.equal(cfg.body.search_turn_speed, math.abs(w[3]))
    assert.is_true(c.body_turning)
    search.exit(c)
  end)

  it('turns at once towards a ball seen before (no look)', function()
    local c = context(100, 2.0, -1.0, 5.0, true)
    c.scan_restart = nil
    search.entry(c)
    assert.is_nil(c.scan_restart)
    c.t = 100.1
    search.update(c)
    assert.equal(-cfg.body.search_turn_speed, c.walks[#c.walks][3]) -- to its side (right)
    search.exit(c)
  end)

  it('steps back at once for a ball lost at the feet (no look)', function()
    local c = context(100, 0.1, 0.0, 1.0, true)
    c.scan_restart = nil
    search.entry(c)
    assert.is_nil(c.scan_restart)
    c.t = 100.5
    search.update(c)
    assert.is_true(c.walks[#c.walks][1] < 0)
    search.exit(c)
  end)
end)

describe('walking kick', function()
  local wk = cfg.body.walk_kick
  -- the fake walk: requests are recorded; `made` kicks done, `phase` the request's state
  local function kick_ctx(bx, walk_vx)
    local c = context(10, bx, 0.06, 0.0, true)
    c.kicks, c.made, c.phase = {}, 0, 'none'
    c.act.motion_state = function() return 'walk' end
    c.act.walk_kicks = function() return c.made end
    c.act.walk_kick_phase = function() return c.phase end
    c.act.walk_velocity = function() return walk_vx, 0, 0 end
    c.act.walk_kick = function(kind, foot, x, y)
      c.kicks[#c.kicks + 1] = { kind, foot, x, y }
      c.phase = 'asked'
      return true
    end
    c.act.walk_kick_cancel = function() c.phase, c.cancelled = 'none', true end
    c.kick_side = 'left'
    return c
  end

  it('closes on a ball beyond the zone before slowing, and kicks once the walk is slow', function()
    assert.is_true(wk.close_gain > 0)
    local c = kick_ctx(wk.x[2] + 0.1, 0.3)
    kick.entry(c)
    kick.update(c)
    local vx = c.walks[#c.walks][1]
    assert.is_true(vx > wk.speed + 0.1, 'walks on faster than the kick speed: ' .. vx)
    assert.equal(0, #c.kicks) -- the walk is too fast to ask
    -- the ball back at the zone's far end and the walk slowed: the kick is asked
    c.world.ball.x = wk.x[2]
    c.act.walk_velocity = function() return wk.max_vx - 0.01, 0, 0 end
    kick.update(c)
    assert.near(wk.speed, c.walks[#c.walks][1], 1e-9)
    assert.same({ { 'forward', 'left', wk.x[2], 0.06 } }, c.kicks)
    -- done once the walk reports the kick
    c.made = 1
    assert.equal('done', kick.update(c))
    kick.exit(c)
  end)

  it('asks again with the ball\'s fresh place until the kick step starts, the head kept on it', function()
    assert.is_true(wk.follow and wk.keep_ball) -- (the OP3's config turns both on)
    local c = kick_ctx(wk.x[2], wk.max_vx - 0.01)
    kick.entry(c)
    assert.is_true(c.keep_ball)
    kick.update(c)
    assert.equal(1, #c.kicks)
    -- the ball rolled on and sideways, seen again: asked again with its new place
    c.world.ball.x, c.world.ball.y = wk.x[2] - 0.03, 0.08
    kick.update(c)
    assert.same({ 'forward', 'left', wk.x[2] - 0.03, 0.08 }, c.kicks[2])
    -- not seen for longer than max_age: its old request stands
    c.world.ball_age = function() return wk.max_age + 0.1 end
    kick.update(c)
    assert.equal(2, #c.kicks)
    -- the kick step has begun: never asked again (a second request would kick twice)
    c.world.ball_age = function() return 0 end
    c.phase = 'kicking'
    kick.update(c)
    kick.update(c)
    assert.equal(2, #c.kicks)
    kick.exit(c)
    assert.is_nil(c.keep_ball)
  end)

  it('keeps the head on the ball: no look at the goal while it waits (keep_ball)', function()
    local c = kick_ctx(wk.x[2], wk.max_vx - 0.01)
    c.world.localised = function() return true end
    c.world.goal_in_robot_frame = function() return 1.0, 0.0 end -- near the goal: looks often
    track.entry(c)
    c.t = 10 + cfg.head.look_goal_every + 0.1
    assert.equal('timeout', track.update(c)) -- (without the kick state: time to look at the goal)
    kick.entry(c)
    track.entry(c)
    c.t = c.t + cfg.head.look_goal_every + 0.1
    assert.is_nil(track.update(c))
    -- a look at the goal already begun ends at once
    lookgoal.entry(c)
    assert.equal('done', lookgoal.update(c))
    kick.exit(c)
    lookgoal.entry(c)
    assert.is_nil(lookgoal.update(c))
  end)

  it('gives up after its timeout when no kick was made', function()
    local c = kick_ctx(wk.x[2], 0.1)
    c.act.walk_kick = function() return false end
    kick.entry(c)
    c.t = 10 + wk.timeout - 0.1
    assert.is_nil(kick.update(c))
    c.t = 10 + wk.timeout + 0.1
    assert.equal('done', kick.update(c))
    kick.exit(c)
    assert.is_nil(c.cancelled) -- nothing was asked: nothing to drop
  end)

  it('drops a request still waiting for its step when it times out', function()
    local c = kick_ctx(wk.x[2], wk.max_vx - 0.01)
    kick.entry(c)
    kick.update(c)
    assert.equal('asked', c.phase)
    c.t = 10 + wk.timeout + 0.1
    assert.equal('done', kick.update(c))
    kick.exit(c)
    assert.is_true(c.cancelled)
    -- a kick already made is not touched
    local k = kick_ctx(wk.x[2], wk.max_vx - 0.01)
    kick.entry(k)
    kick.update(k)
    k.phase, k.made = 'kicking', 1
    assert.equal('done', kick.update(k))
    kick.exit(k)
    assert.is_nil(k.cancelled)
  end)
end)
