-- luacheck: std +busted
-- The rules of a game under a GameController (packets built here, sent over UDP to the behavior;
-- the robot's return packets read back on a test port): kick-off, each set play, timeout, the
-- chest button and "alive". The robot's clock and vision are driven by the test (no simulator);
-- what the behavior asks of the walk is read from the motion block. Numbers: Config/common/game.lua.
local shm = require('shm')
local view = require('Tests.behavior.view')
local packet = require('GameFSM.packet')
local udp = require('GameFSM.udp')
local Motion = require('Motion')
local Config = require('Config')

describe('behavior under the rules of a game', function()
  local id = tonumber(os.getenv('ROBOT_ID') or '1')
  local port, rport = 21000 + (id % 20000), 41000 + (id % 20000)
  local rules = Config.load('game')
  local behavior, sensor, vision, motion, game, tx, gc_side
  local tick, number = 0, 0
  local ball = { 1.0, 0.0 } -- where vision sees the ball (robot frame)
  local TEAM, OTHER = 1, 9

  setup(function()
    sensor, vision = shm.open('dcm.sensor'), shm.open('vision')
    motion, game = shm.open('motion'), shm.open('game')
    sensor.time[0], sensor.tick[0] = 100, 0
    behavior = require('Behavior.behavior').new({ port = port, return_port = rport, team_port = port + 2,
      fresh = true })
    tx = assert(udp.sender())
    gc_side = assert(udp.listen(rport))
  end)

  teardown(function()
    behavior:close()
    tx:close()
    gc_side:close()
    if os.getenv('ROBOT_ID') then for _, name in ipairs(shm.block_names()) do shm.unlink(name) end end
  end)

  -- the robot's view: the ball where `ball` says, the opponent goal's posts as seen from (-2, 0)
  local function run(seconds)
    for _ = 1, math.floor(seconds / 0.024 + 0.5) do
      tick = view.frame(sensor, vision, tick, ball[1], ball[2])
      behavior:step()
    end
  end

  -- the robot's button pressed for 0.1 s and released
  local function press_button()
    sensor.button[0] = 1
    run(0.1)
    sensor.button[0] = 0
    run(0.1)
  end

  local function send(state, o)
    o = o or {}
    number = (number + 1) % 256
    assert(tx:send(packet.build({ state = state, packet_number = number, kickoff_team = o.kickoff or TEAM,
      secondary_state = o.secondary or 0, secondary_state_info = { o.team or 0, o.mode or 0, 0, 0 },
      teams = { { number = OTHER }, { number = TEAM, players = { { penalty = o.penalty or 0 } } } } }),
      '127.0.0.1', port))
  end

  local function vel() return motion.velocity[0], motion.velocity[1], motion.velocity[2] end
  local function speed() local a, b, c = vel() return math.abs(a) + math.abs(b) + math.abs(c) end
  local function kicked() local r = Motion.requested() return r == 'kick_left' or r == 'kick_right' end
  -- return packets received so far, parsed
  local function returns()
    local list = {}
    while true do
      local data = gc_side:receive()
      if not data then return list end
      list[#list + 1] = assert(packet.parse_return(data))
    end
  end
  local function kickoff(team)
    send(packet.STATE.ready, { kickoff = team }) run(0.5)
    send(packet.STATE.set, { kickoff = team }) run(0.5)
    send(packet.STATE.playing, { kickoff = team })
  end

  it("the other team's kick-off: keeps away from the ball until it has moved", function()
    ball = { 0.5, 0.0 }
    kickoff(OTHER)
    run(2)
    assert.are.equal(1, game.setplay[0]) -- keep away
    local vx = vel()
    assert.is_true(vx < 0, 'backs off the ball: vx ' .. vx)
    assert.is_false(kicked())
    ball = { 1.2, 0.0 } -- kicked off: the ball rolls 0.7 m away
    run(0.5)
    assert.are.equal(0, game.setplay[0]) -- play
    assert.are_not.equal('idle', behavior.body:state())
  end)

  it("the other team's kick-off: plays after the wait when the ball stays put", function()
    ball = { 1.5, 0.0 } -- already outside the circle: stands facing the ball
    kickoff(OTHER)
    run(1)
    assert.are.equal(1, game.setplay[0])
    assert.are.equal(0, speed())
    run(rules.kickoff.wait - 1.6)
    assert.are.equal(1, game.setplay[0])
    run(0.8)
    assert.are.equal(0, game.setplay[0])
    assert.is_true(speed() > 0)
  end)

  it('our kick-off: plays at once', function()
    ball = { 0.5, 0.0 }
    kickoff(TEAM)
    run(0.3)
    assert.are.equal(0, game.setplay[0])
    assert.are_not.equal('idle', behavior.body:state())
  end)

  for code = 4, 9 do
    local name = packet.SECONDARY[code]
    local d = rules.setplay.distance[name]
    it(string.format("the other team's %s: stays %.2f m from the ball", name, d), function()
      send(packet.STATE.playing, { kickoff = OTHER })
      run(0.3)
      ball = { d - 0.2, 0.1 }
      send(packet.STATE.playing, { secondary = code, team = OTHER, mode = 0 })
      run(1)
      assert.are.equal(code, game.secondary_state[0])
      assert.are.equal(OTHER, game.secondary_team[0])
      assert.are.equal(1, game.setplay[0])
      local vx, vy = vel()
      assert.is_true(vx < 0, 'backs off: vx ' .. vx)
      assert.is_true(vy <= 0, 'away from a ball on its left: vy ' .. vy)
      assert.is_false(kicked())
      ball = { d + rules.setplay.margin + rules.setplay.hysteresis + 0.3, 0.0 }
      run(1)
      assert.are.equal(0, speed()) -- far enough: stands facing the ball
      send(packet.STATE.playing, { secondary = code, team = OTHER, mode = 2 }) -- execute: still theirs
      run(0.5)
      assert.are.equal(1, game.setplay[0])
      send(packet.STATE.playing, { kickoff = OTHER }) -- over: play on
      run(0.5)
      assert.are.equal(0, game.setplay[0])
    end)
  end

  it('our free kick: goes behind the ball without kicking, stands while placing, plays on execute', function()
    ball = { 1.0, 0.2 }
    send(packet.STATE.playing, { secondary = 4, team = TEAM, mode = 0 })
    run(2)
    assert.are.equal(2, game.setplay[0]) -- take
    assert.is_true(speed() > 0)
    ball = { 0.35, 0.0 } -- right in front: in a real game it would kick now
    run(2)
    assert.is_false(kicked())
    send(packet.STATE.playing, { secondary = 4, team = TEAM, mode = 1 })
    run(0.5)
    assert.are.equal(3, game.setplay[0]) -- stand
    assert.are.equal(0, speed())
    send(packet.STATE.playing, { secondary = 4, team = TEAM, mode = 2 })
    run(0.5)
    assert.are.equal(0, game.setplay[0]) -- play
    assert.are_not.equal('idle', behavior.body:state())
  end)

  it('decides what the rules allow for every secondary state, team, mode and role', function()
    local setplay = require('GameFSM.setplay')
    local function g(secondary, ours, mode, o)
      local v = { gc = true, secondary = secondary, secondary_ours = ours, secondary_mode = mode,
        our_kickoff = true, dropball = false }
      for k, x in pairs(o or {}) do v[k] = x end
      return v
    end
    assert.are.same({ 'play' }, { setplay.decide(g('normal'), rules) })
    assert.are.same({ 'play' }, { setplay.decide(g('overtime'), rules) })
    assert.are.same({ 'stand' }, { setplay.decide(g('timeout'), rules) })
    assert.are.same({ 'play' }, { setplay.decide(g('penalty_shootout'), rules) })
    assert.are.same({ 'stand' }, { setplay.decide(g('penalty_shootout', false, nil, { our_kickoff = false }), rules) })
    assert.are.same({ 'guard' }, { setplay.decide(g('penalty_shootout', false, nil, { our_kickoff = false }), rules,
      nil, 'goalkeeper') })
    for code = 4, 9 do
      local s = packet.SECONDARY[code]
      assert.are.same({ 'take' }, { setplay.decide(g(s, true, 'preparation'), rules) })
      assert.are.same({ 'stand' }, { setplay.decide(g(s, true, 'placing'), rules) })
      assert.are.same({ 'play' }, { setplay.decide(g(s, true, 'end'), rules) })
      for _, mode in ipairs({ 'preparation', 'placing', 'end' }) do
        assert.are.same({ 'keep_away', rules.setplay.distance[s] }, { setplay.decide(g(s, false, mode), rules) })
      end
    end
    assert.are.same({ 'guard' }, { setplay.decide(g('penalty_kick', false, 'preparation'), rules, nil, 'goalkeeper') })
    assert.are.same({ 'keep_away', rules.setplay.distance.corner_kick },
      { setplay.decide(g('corner_kick', false, 'preparation'), rules, nil, 'goalkeeper') })
    -- kick-off: the other team's holds us back until the ball moved or the wait is over; a drop ball does not
    local theirs = g('normal', nil, nil, { our_kickoff = false })
    assert.are.same({ 'keep_away', rules.kickoff.distance },
      { setplay.decide(theirs, rules, { since = 1, ball_moved = false }) })
    assert.are.same({ 'play' }, { setplay.decide(theirs, rules, { since = 1, ball_moved = true }) })
    assert.are.same({ 'play' }, { setplay.decide(theirs, rules, { since = rules.kickoff.wait, ball_moved = false }) })
    assert.are.same({ 'play' }, { setplay.decide(g('normal', nil, nil, { our_kickoff = false, dropball = true }),
      rules, { since = 1, ball_moved = false }) })
    assert.are.same({ 'play' }, { setplay.decide({ gc = false }, rules, { since = 1, ball_moved = false }) })
  end)

  it('a timeout: stands', function()
    send(packet.STATE.playing, { secondary = 3 })
    run(1)
    assert.are.equal(3, game.setplay[0])
    assert.are.equal(0, speed())
  end)

  it('our free kick with a teammate at the ball: only the striker goes behind it, the defender to its place', function()
    local rc = setmetatable({ broadcast = '127.255.255.255' }, { __index = rules.team })
    local mate = require('Team.team').new({ team_number = TEAM, player_number = 2, team = rc }, { port = port + 2 })
    ball = { 1.0, 0.0 } -- the robot at (-2, 0) facing the opponent goal, the ball at (-1, 0)
    local function with_mate(seconds)
      for _ = 1, math.floor(seconds / 0.1 + 0.5) do
        mate:update(sensor.time[0], { pose = { -1.3, 0.0, 0 }, ball = { -1.0, 0.0, 0, 0 }, penalised = false,
          walk = { 0, 0, 0 }, target = { -1.0, 0.0, 0 } }) -- it stands behind the ball and says it strikes
        run(0.1)
      end
    end
    send(packet.STATE.playing, { secondary = 4, team = TEAM, mode = 0 })
    with_mate(3)
    mate:close()
    assert.are.equal(2, game.setplay[0]) -- take
    assert.are.equal(require('Team.roles').INDEX.defender, game.role[0])
    -- the defender's place (defender_gap short of the ball towards its goal) is where it stands: it
    -- stays (taking the free kick, it walked on to the ball at 0.38 m/s)
    assert.are.equal(1.0, rules.roles.defender_gap)
    local vx, _, va = vel()
    assert.is_true(vx <= 0.01, string.format('walk %.3f %.3f', vx, va))
    send(packet.STATE.playing) -- normal play; the teammate is lost after team.lost_after s
    run(rules.team.lost_after + 0.5)
  end)

  it('says alive about once a second and reports the button; the packets decide', function()
    returns()
    send(packet.STATE.playing)
    run(5)
    local r = returns()
    assert.is_true(#r >= 4 and #r <= 6, #r .. ' return packets in 5 s')
    for _, p in ipairs(r) do
      assert.are.same({ version = 2, team = TEAM, player = 1, message = packet.MSG.alive }, p)
    end
    press_button()
    r = returns()
    assert.are.equal(packet.MSG.man_penalise, r[1].message)
    assert.are.equal(0, game.penalized[0]) -- asked, not penalized by itself
    send(packet.STATE.playing, { penalty = 34 })
    run(0.5)
    assert.are.equal(1, game.penalized[0])
    assert.are.equal(0, speed())
    returns()
    press_button()
    r = returns()
    assert.are.equal(packet.MSG.man_unpenalise, r[1].message)
    assert.are.equal(1, game.penalized[0])
    assert.are.equal(game.returns[0], behavior.gc.returns)
  end)
end)
