-- luacheck: std +busted
-- The sim's automatic referee (Tools/match/rules.lua): its rules on a scripted world, with the
-- numbers of Config/common/game.lua and the sim's field; the packets go through GameFSM/packet.lua.
local match = require('Tools.match.rules')
local packet = require('GameFSM.packet')
local Config = require('Config')

local rules = Config.load('game').referee
local field = { length = 9, width = 6, goal_width = 2.6, ball_diameter = 0.14, penalty_mark_distance = 1.5,
  goal_area_length = 1, goal_area_width = 3 }
local S = packet.STATE

local function world(ball, robots, score)
  return { ball = ball, score = score or { 0, 0 }, robots = robots or {
    { team = 1, player = 1, x = -1, y = 0, roll = 0, pitch = 0, fallen = false },
    { team = 2, player = 1, x = 1, y = 0, roll = 0, pitch = 0, fallen = false } } }
end

-- A match brought to PLAYING at time t (returned); the packets round-trip through build/parse.
local function playing()
  local m = match.new(rules, field, { { number = 1, players = { 1 } }, { number = 2, players = { 1 } } })
  local t = 0
  local acts = m:step(t, world({ 0, 0 }))
  assert.are.equal(2, #acts)                       -- both robots placed beside the touch line
  assert.are.equal(-3, acts[1][4])
  assert.is_true(acts[1][3] < 0 and acts[2][3] > 0) -- each in its own half
  for _ = 1, 3 do
    t = t + rules.initial_time + rules.ready_time + rules.set_time
    m:step(t, world({ 0, 0 }))
  end
  assert.are.equal(S.playing, m.state)
  return m, t
end

local function parsed(m) return packet.parse(packet.build(m:packet())) end

describe('the referee', function()
  it('goes INITIAL, READY, SET, PLAYING with team 1 kicking off', function()
    local m = playing()
    local p = parsed(m)
    assert.are.equal(S.playing, p.state)
    assert.are.equal(1, p.kickoff_team)
    assert.are.equal(1, p.first_half)
    assert.are.equal(1, p.teams[1].players[1].goalkeeper)
  end)

  it('gives a throw-in to the other team than the last to touch, the ball on the line', function()
    local m, t = playing()
    m:step(t + 0.1, world({ 1.05, 2.8 }))           -- team 2's robot (at 1, 0) is not near; nobody touched
    local w = world({ 1.2, 2.9, 0.5, 0.5 })             -- kicked: the velocity changed
    w.robots[2].x, w.robots[2].y = 1.1, 2.7         -- team 2 touches it
    m:step(t + 0.2, w)
    local acts = m:step(t + 0.3, world({ 1.3, 3.2 }))
    assert.are.same({ 'ball', 1.3, 3 }, acts[1])
    local p = parsed(m)
    assert.are.equal(9, p.secondary_state)
    assert.are.same({ 1, 0, 0, 0 }, p.secondary_state_info)
    m:step(t + 0.3 + rules.setplay_prepare, world({ 1.3, 3 }))
    assert.are.equal(2, parsed(m).secondary_state_info[2]) -- execute
    m:step(t + 0.5 + rules.setplay_prepare, world({ 1.3, 2.5 }))
    assert.are.equal(0, parsed(m).secondary_state)      -- taken: normal play
  end)

  it('gives a goal kick or a corner kick over the goal line', function()
    local m, t = playing()
    local w = world({ 3.9, -2, 1, 0 })
    w.robots[1].x, w.robots[1].y = 3.8, -2.1           -- team 1 (attacking +x) touched it last
    m:step(t + 0.1, w)
    local acts = m:step(t + 0.2, world({ 4.7, -2 }))
    assert.are.same({ 'ball', 3.5, -1.5 }, acts[1])
    assert.are.equal(8, parsed(m).secondary_state)
    assert.are.equal(2, parsed(m).secondary_state_info[1])
    m, t = playing()
    w = world({ 3.9, 2, 1, 0 })
    w.robots[2].x, w.robots[2].y = 3.8, 2.1            -- the defenders touched it last
    m:step(t + 0.1, w)
    acts = m:step(t + 0.2, world({ 4.7, 2 }))
    assert.are.same({ 'ball', 4.5, 3 }, acts[1])
    assert.are.equal(7, parsed(m).secondary_state)
    assert.are.equal(1, parsed(m).secondary_state_info[1])
  end)

  it('penalizes a robot fallen too long and puts it back on its own touch line', function()
    local m, t = playing()
    local w = world({ 0, 0 })
    w.robots[1].fallen, w.robots[1].pitch = true, 1.3
    m:step(t + 0.1, w)
    local acts = m:step(t + 0.2 + rules.fallen_time, w)
    assert.are.equal('robot', acts[1][1])
    assert.is_true(math.abs(acts[1][4]) > 3)          -- off the field
    local p = parsed(m)
    assert.are.equal(rules.penalty_code, p.teams[1].players[1].penalty)
    assert.is_true(p.teams[1].players[1].secs_till_unpenalised > 0)
    assert.are.equal(1, m.stats.falls[1])
    acts = m:step(t + 0.3 + rules.fallen_time + rules.penalty_time, world({ 0, 1 }))
    assert.are.same({ 'robot', 1, -3, -3, math.pi / 2 }, acts[1]) -- the touch line away from the ball
    assert.are.equal(0, parsed(m).teams[1].players[1].penalty)
    assert.are.equal(1, m.stats.penalties[1])
  end)

  it('penalizes a robot that leaves the field', function()
    local m, t = playing()
    local w = world({ 0, 0 })
    w.robots[2].y = -3.5
    m:step(t + 0.1, w)
    assert.are.equal(rules.penalty_code, parsed(m).teams[2].players[1].penalty)
  end)

  it('after a goal: READY, the other team kicks off; counts own goals', function()
    local m, t = playing()
    local w = world({ -3.9, 0, -1, 0 })
    w.robots[1].x = -3.8                               -- team 1 touches it last, into its own goal
    m:step(t + 0.1, w)
    local acts = m:step(t + 0.2, world({ -4.7, 0 }, nil, { 0, 1 }))
    assert.are.same({ 'ball', 0, 0 }, acts[1])
    assert.are.equal(S.ready, m.state)
    local p = parsed(m)
    assert.are.equal(1, p.teams[2].score)
    assert.are.equal(1, p.kickoff_team)
    assert.are.equal(1, m.stats.own_goals[1])
  end)

  it("takes the last touch from the sim's contacts when the world has them, not the nearest robot", function()
    local m, t = playing()
    -- team 1's defender stands nearest, but the physics says team 2's attacker touched it last: a goal,
    -- not an own goal (the seed-3 league match that the nearest-robot rule called an own goal)
    local w = world({ -4.3, 0, -0.3, 0 })
    w.robots[1].x, w.robots[1].y = -4.25, 0.05
    w.robots[2].x, w.robots[2].y = -4.0, 0
    w.touch = 2
    m:step(t + 0.1, w)
    local g = world({ -4.7, 0 }, nil, { 0, 1 })
    g.touch = 2
    m:step(t + 0.2, g)
    assert.are.equal(0, m.stats.own_goals[1])
    assert.are.equal(1, m.stats.goals[2])
    -- the same scene with the defender's touch: an own goal; `false` (placed since) keeps the last
    m, t = playing()
    w.touch = 1
    m:step(t + 0.1, w)
    g.touch = false
    m:step(t + 0.2, g)
    assert.are.equal(1, m.stats.own_goals[1])
  end)

  it('changes ends at half time and finishes after the second half', function()
    local m, t = playing()
    t = t + rules.half_time + 0.1
    m:step(t, world({ 0, 0 }))
    assert.are.equal(S.finished, m.state)
    local acts = m:step(t + rules.break_time, world({ 0, 0 }))
    assert.is_true(acts[1][3] > 0 and acts[2][3] < 0) -- team 1 now in the +x half
    local p = parsed(m)
    assert.are.equal(S.initial, p.state)
    assert.are.equal(0, p.first_half)
    assert.are.equal(2, p.kickoff_team)
    assert.is_false(m.over)
    for _ = 1, 3 do
      t = t + rules.initial_time + rules.ready_time + rules.set_time + rules.break_time
      m:step(t, world({ 0, 0 }))
    end
    m:step(t + 0.1, world({ 4.7, 0 }, nil, { 1, 0 })) -- into +x: now team 2's goal
    assert.are.equal(1, m.score[2])
    m:step(t + 0.2, world({ 0, 0 }, nil, { 1, 0 }))
    for _ = 1, 3 do
      t = t + rules.initial_time + rules.ready_time + rules.set_time
      m:step(t, world({ 0, 0 }, nil, { 1, 0 }))
    end
    m:step(t + rules.half_time, world({ 0, 0 }, nil, { 1, 0 }))
    assert.is_true(m.over)
    assert.are.equal(S.finished, parsed(m).state)
  end)
end)
