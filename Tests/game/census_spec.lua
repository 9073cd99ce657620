-- luacheck: std +busted
-- The fall census (Tools/match/census.lua) on crafted truth records: the tip found before the truth's fallen,
-- each cause from its record, the first cause in the census's order, the measured speed, the table.
local census = require('Tools.match.census')
local params = require('Config').load('game').referee.census

-- A robot walking along +x at vx m/s (looks every 0.1 s from t0 for n looks), upright; fields of `over`
-- replace those of every record.
local function walk(n, vx, over, t0)
  local h = {}
  for k = 1, n do
    local t = (t0 or 0) + 0.1 * (k - 1)
    local r = { t = t, x = vx * t, y = 0, yaw = 0, roll = 0, pitch = 0.02, fallen = false, state = 'walk',
      cmd = { vx, 0, 0 }, others = {} }
    for key, v in pairs(over or {}) do r[key] = v end
    h[k] = r
  end
  return h
end

-- Feeds h to a census, then tips the robot forward over three looks and reports that (the last) fall.
local function fall(h, last)
  local c = census.new(params, { 'r1' })
  local f
  for _, r in ipairs(h) do c:look(1, r) end
  local t, x = h[#h].t, h[#h].x
  for k, p in ipairs({ 0.4, 0.7, 1.2 }) do
    local r = { t = t + 0.1 * k, x = x, y = h[#h].y, yaw = h[#h].yaw, roll = 0, pitch = p, fallen = p > 1.0,
      state = k == 1 and (h[#h].state) or 'falling', cmd = h[#h].cmd, others = h[#h].others, ball = h[#h].ball }
    for key, v in pairs(last or {}) do r[key] = v end
    f = f or c:look(1, r)
  end
  return f, c
end

describe('fall census', function()
  it('finds the tip: the last look under the tip angle before the truth says fallen', function()
    local h = walk(10, 0.2)
    h[#h + 1] = { t = 1.0, x = 0.2, y = 0, yaw = 0, roll = 0.35, pitch = 0.1, fallen = false }
    h[#h + 1] = { t = 1.1, x = 0.2, y = 0, yaw = 0, roll = 1.1, pitch = 0.1, fallen = true }
    assert.are.equal(10, census.tip_index(params, h))
  end)

  it('calls a fall while walking straight "walking", with the commanded and measured speed', function()
    local f = fall(walk(20, 0.25))
    assert.are.equal('walking', f.cause)
    assert.are.same({ 'walking', 'standing' }, f.causes)
    assert.are.equal(0.25, f.cmd[1])
    assert.is_near(0.25, f.speed[1], 1e-9)
    assert.is_near(0, f.speed[2], 1e-9)
    assert.are.equal('front', f.tilt_dir)
    assert.is_near(0.25 * 1.9, f.x, 1e-9)
  end)

  it('calls a fall in stance with no command "standing"', function()
    local f = fall(walk(20, 0, { state = 'stance', cmd = { 0, 0, 0 } }))
    assert.are.equal('standing', f.cause)
  end)

  it('tells a turn and a sideways step from a straight walk, commanded or measured', function()
    assert.are.equal('turn', fall(walk(20, 0.1, { cmd = { 0.1, 0, 0.5 } })).cause)
    assert.are.equal('turn', fall(walk(20, 0.1, { cmd = { 0.1, 0.08, 0 } })).cause)
    -- commanded straight, but the torso turns at 0.5 rad/s (the walk spinning on its foot)
    local h = walk(20, 0.2)
    for _, r in ipairs(h) do r.yaw = 0.5 * r.t end
    assert.are.equal('turn', fall(h).cause)
    -- a turn more than the window before the tip does not count
    h = walk(20, 0.2)
    for k = 1, 5 do h[k].cmd = { 0.2, 0, 1.0 } end
    assert.are.equal('walking', fall(h).cause)
  end)

  it('sees another robot within the contact distance', function()
    local f = fall(walk(20, 0.2, { others = { { 10, 10 } } }), { others = { { 10, 10 } } })
    assert.are.equal('walking', f.cause)
    local h = walk(20, 0.2, { others = { { 10, 10 } } })
    h[18].others = { { h[18].x + 0.25, 0.05 } }
    assert.are.equal('contact', fall(h).cause)
  end)

  it('sees the ball at a foot, and a ball further away not', function()
    local h = walk(20, 0.2)
    for _, r in ipairs(h) do r.ball = { r.x + 0.5, 0 } end
    assert.are.equal('walking', fall(h).cause)
    for _, r in ipairs(h) do r.ball = { r.x + 0.15, 0.05 } end
    local f = fall(h)
    assert.are.equal('ball', f.cause)
    assert.are.same({ 'ball', 'walking', 'standing' }, f.causes)
  end)

  it('sees the goal frame (posts, nets) near the torso, and the goal mouth not', function()
    local field = { length = 9.0, goal_width = 2.6, goal_depth = 0.6 }
    assert.is_near(0.1, census.goal_distance(field, 4.8, -1.2), 1e-9)        -- beside the side net
    assert.is_near(0.2, census.goal_distance(field, 5.3, 0.3), 1e-9)         -- before the back net
    assert.is_near(0.5, census.goal_distance(field, -4.0, 1.3), 1e-9)        -- ahead of a post
    assert.is_near(0.9, census.goal_distance(field, 4.2, 0.0), 1e-9)         -- before the mouth: the back net
    local h = walk(20, 0.3)
    for _, r in ipairs(h) do r.x, r.y, r.ball = r.x + 4.5, 0, { 4.9, 0 } end
    local c = census.new(params, { 'r1' }, field)
    for _, r in ipairs(h) do c:look(1, r) end
    local f = c:look(1, { t = 2.0, x = 4.8, y = 0, yaw = 0, roll = 0, pitch = -1.2, fallen = true, state = 'walk' })
    assert.are.equal('goal', f.cause)
    assert.are.equal('back', f.tilt_dir)
    -- the same walk in the middle of the field
    assert.are.equal('walking', fall(walk(20, 0.3)).cause)
  end)

  it('ranks a kick, a failed stand-up and a push before the rest', function()
    local h = walk(20, 0.1, { ball = { 1.0, 0 } })
    h[19].state = 'kick_left'
    for _, r in ipairs(h) do r.ball = { r.x + 0.15, 0 } end
    assert.are.equal('kick', fall(h).cause)
    h = walk(20, 0.1)
    h[19].kick = true
    assert.are.equal('kick', fall(h).cause)
    -- lying 3 s before the tip, then a stand-up, then down again
    h = walk(40, 0.0, { state = 'stance', cmd = { 0, 0, 0 } })
    h[5].fallen = true
    for k = 6, 30 do h[k].state = 'standup_front' end
    local f = fall(h)
    assert.are.equal('standup', f.cause)
    -- that long ago, no
    h = walk(70, 0.0, { state = 'stance', cmd = { 0, 0, 0 } })
    h[5].fallen = true
    assert.are.equal('standing', fall(h).cause)
    -- a push 0.5 s before the tip
    local c = census.new(params)
    h = walk(20, 0.2, { ball = { 5, 5 } })
    for k = 1, 15 do c:look(1, h[k]) end
    c:push(1, h[15].t)
    for k = 16, 20 do c:look(1, h[k]) end
    c:look(1, { t = 2.0, x = 0.4, y = 0, yaw = 0, roll = 0.9, pitch = 0, fallen = false, state = 'walk' })
    f = c:look(1, { t = 2.1, x = 0.4, y = 0, yaw = 0, roll = 1.3, pitch = 0, fallen = true, state = 'falling' })
    assert.are.equal('push', f.cause)
    assert.are.equal('right', f.tilt_dir)
  end)

  it('counts one fall per lying, and prints the table and the CSV', function()
    local c = census.new(params, { 'a', 'b' })
    local h = walk(20, 0.2)
    for _, r in ipairs(h) do c:look(1, r) c:look(2, r) end
    for k = 1, 5 do
      local f = c:look(2, { t = 2 + 0.1 * k, x = 0, y = 0, yaw = 0, roll = 0, pitch = 1.2, fallen = true })
      if k > 1 then assert.is_nil(f) end
    end
    -- rolling about on the ground, the torso under the fall angle for a moment: the same fall
    c:look(2, { t = 2.6, x = 0, y = 0, yaw = 0, roll = 0, pitch = 0.9, fallen = false })
    assert.is_nil(c:look(2, { t = 2.7, x = 0, y = 0, yaw = 0, roll = 0, pitch = 1.2, fallen = true }))
    assert.are.equal(1, #c.falls)
    assert.are.equal('b', c.falls[1].name)
    local lines = c:table(2.0)
    assert.matches('1 falls in 2.0 robot%-minutes = 0.50 per robot%-minute', lines[1])
    assert.matches('walking straight', lines[3])
    assert.matches('fall b: walking straight', census.line(c.falls[1]))
    local path = os.tmpname()
    c:write_csv(path)
    local fh = io.open(path)
    local text = fh:read('*a')
    fh:close()
    os.remove(path)
    assert.matches('^robot,name,t,cause', text)
    assert.matches('\n2,b,1%.90,walking,', text)
  end)

  it('names the key of a bad parameter', function()
    assert.has_error(function() census.new({ tip_angle = 0.3 }) end,
      'census: referee.census.window (Config/common/game.lua) must be a number >= 0, got nil')
  end)

  -- A crafted lying-about: { fallen, tilt (rad, as pitch) } per look, 0.1 s apart.
  local SEQ = {
    { false, 0.02 }, { false, 0.2 }, { false, 0.6 }, { true, 1.3 },      -- fall 1
    { true, 1.5 }, { false, 0.9 }, { true, 1.2 }, { false, 1.0 }, { true, 1.4 }, -- rolling: the flag flickers
    { false, 0.5 }, { true, 1.1 },                                       -- a stand-up that stays tilted, back down
    { false, 0.35 }, { false, 0.1 }, { false, 0.02 },                    -- up
    { false, 0.4 }, { true, 1.2 },                                       -- fall 2
    { false, 0.02 }, { true, 1.3 },                                      -- put back upright (a penalty), fall 3
  }
  local function rec(k, q) return { t = 0.1 * k, x = 0, y = 0, yaw = 0, roll = 0, pitch = q[2], fallen = q[1] } end

  it('counts a fall only when the robot got up between falls (census.fell)', function()
    local down, n, edges, was = nil, 0, 0, false
    for k, q in ipairs(SEQ) do
      local fell
      fell, down = census.fell(down, rec(k, q), params.tip_angle)
      if fell then n = n + 1 end
      if q[1] and not was then edges = edges + 1 end   -- the sim's flag switching on
      was = q[1]
    end
    assert.are.equal(3, n)
    assert.are.equal(6, edges)
    assert.has_error(function() census.fell(nil, { fallen = true }, 0.3) end,
      "census.fell: a look needs the truth's roll and pitch (numbers)")
  end)

  it('gives the referee, the tally and the census one count on the same looks', function()
    local rules_mod, tally_mod = require('Tools.match.rules'), require('Tools.match.tally')
    local rules = require('Config').load('game').referee
    local field = { length = 9, width = 6, goal_width = 2.6, ball_diameter = 0.14, penalty_mark_distance = 1.5,
      goal_area_length = 1, goal_area_width = 3 }
    local m = rules_mod.new(rules, field, { { number = 1, players = { 1 } }, { number = 2, players = { 1 } } })
    local tl = tally_mod.new({ { team = 1, player = 1 }, { team = 2, player = 1 } }, rules.census.tip_angle)
    local c = census.new(params, { '1/1', '2/1' })
    local still = { team = 2, player = 1, x = 1, y = 0, roll = 0, pitch = 0, fallen = false }
    -- robot 1 goes through the sequence twice: in INITIAL/READY (the referee counts in every state) and on
    for pass = 0, 1 do
      for k, q in ipairs(SEQ) do
        local r = rec(pass * #SEQ + k, q)
        r.team, r.player, r.state = 1, 1, 'stance'
        m:step(r.t, { ball = { 0, 0 }, score = { 0, 0 }, robots = { r, still } })
        tl:look(0.1, true, 1, r, nil, 1, false)
        c:look(1, r)
      end
    end
    assert.are.equal(6, #c.falls)
    assert.are.same({ 6, 0 }, m.stats.falls)
    assert.are.equal(6, tl.robots[1].falls)
    assert.has_error(function() rules_mod.new({}, field, {}) end,
      'rules: referee.census.tip_angle (Config/common/game.lua) must be a number > 0, got nil')
  end)
end)
