-- luacheck: std +busted
-- Team communication over UDP (Player/Team/team.lua): teammates' messages into a bounded table and
-- the world model, another team's and malformed messages ignored and counted, our own broadcasts
-- recognised, a flood read in bounded steps. Loopback broadcast on a port of this test's own.
local shm = require('shm')
local Team = require('Team.team')
local message = require('Team.message')
local udp = require('GameFSM.udp')
local Config = require('Config')

local id = tonumber(os.getenv('ROBOT_ID') or '1')
local PORT = 22000 + (id % 20000)
local rules = Config.load('game')
local tc = setmetatable({ broadcast = '127.255.255.255' }, { __index = rules.team })

local function robot(player, port)
  return Team.new({ team_number = 1, player_number = player, team = tc }, { port = port })
end
local function me(x, ball)
  return { pose = { x, 0.5, 0.25 }, ball = ball, penalised = false, colour = 0, walk = { 0.1, 0, 0 } }
end

describe('team communication', function()
  local a, b, tx
  setup(function()
    a, b = robot(1, PORT), robot(2, PORT)
    tx = assert(udp.sender())
  end)
  teardown(function()
    a:close() b:close() tx:close()
    if os.getenv('ROBOT_ID') then for _, name in ipairs(shm.block_names()) do shm.unlink(name) end end
  end)

  it('teammates hear each other: poses and balls into the table; their own broadcast is recognised', function()
    a:update(10.0, me(-1.0, { 2.0, -1.0, 0.5, 0 }))
    b:update(10.0, me(-3.0, nil))
    a:update(10.1, me(-1.0, nil))
    b:update(10.1, me(-3.0, nil))
    local ma, mb = a:mates(10.1), b:mates(10.1)
    assert.are.equal(1, #ma)
    assert.are.equal(2, ma[1].player)
    assert.are.equal(-3.0, ma[1].pose[1])
    assert.is_false(ma[1].ball_known)
    assert.are.equal(1, #mb)
    assert.are.equal(1, mb[1].player)
    assert.is_true(mb[1].ball_known)
    assert.are.same({ 2.0, -1.0, 0.5, 0 }, mb[1].ball)
    assert.is_true(math.abs(mb[1].pose[3] - 0.25) < 1e-6)
    assert.is_nil(ma[1].target) -- none sent
    assert.are.equal(1, a.own) -- its own message came back on the broadcast
    assert.are.equal(1, a.received)
    assert.are.equal(1, a.sent)
  end)

  it('ignores and counts another team\'s and malformed messages', function()
    local r0, f0, m0 = a.received, a.foreign, a.malformed
    local function send(s) assert(tx:send(s, '127.255.255.255', PORT)) end -- unicast reaches one socket
    send(message.encode({ player_id = 3, team = 'red', pose = { 1, 1, 0 } }))    -- their colour
    send('not a protobuf \255\255\255')                                          -- garbage
    send(message.encode({ player_id = 0, team = 'blue', pose = { 1, 1, 0 } })) -- no player number
    send(message.encode({ player_id = 12, team = 'blue', pose = { 1, 1, 0 } })) -- out of range
    send('')                                                                     -- no sender at all
    send(string.rep('\10\0', 1500))                                              -- too long
    -- found by Tests/team/teamcomm_fuzz_test.sh: a NaN pose was taken into the table
    send(message.encode({ player_id = 5, team = 'blue', pose = { 0 / 0, 1, 0 } }))     -- not a number
    send(message.encode({ player_id = 6, team = 'blue', pose = { 1, 1, 0 }, ball = { math.huge, 0 } }))
    send(message.encode({ player_id = 8, team = 'blue', pose = { 1, 1, 0 }, target = { pose = { 0 / 0, 0, 0 } } }))
    -- a NaN whose payload LuaJIT would read as a table at a wild address (the pose's x: 1.5's bytes
    -- replaced by the float ff900001): decoded as NaN, ignored
    local hostile = message.encode({ player_id = 7, team = 'blue', pose = { 1.5, 1, 0 } })
    local at = assert(hostile:find('\0\0\192\63', 1, true))
    send(hostile:sub(1, at - 1) .. '\1\0\144\255' .. hostile:sub(at + 4))
    send(message.encode({ player_id = 4, team = 'blue', pose = { 2, 2, 0 } }))  -- a teammate
    a:update(11.0, me(-1.0, nil))
    assert.are.equal(f0 + 1, a.foreign)
    assert.are.equal(m0 + 9, a.malformed)
    assert.are.equal(r0 + 1, a.received)
    local players = {}
    for _, s in ipairs(a:mates(11.0)) do players[#players + 1] = s.player end
    table.sort(players)
    assert.are.same({ 2, 4 }, players)
  end)

  it('a teammate\'s target (where it goes) into the table, and gone when it sends none', function()
    local target = { 1.0, -0.5, 0 }
    local m = me(-3.0, { 1.0, -0.5, 0, 0 })
    m.target = target
    b:update(12.0, m)
    a:update(12.0, me(-1.0, nil))
    local mate = a:mates(12.0)[1]
    assert.are.equal(2, mate.player)
    assert.are.same(target, mate.target)
    b:update(12.6, me(-3.0, nil))
    a:update(12.6, me(-1.0, nil))
    assert.is_nil(a:mates(12.6)[1].target)
  end)

  it('a teammate that is down says so (our extension field), and the table follows it', function()
    local m = me(-3.0, nil)
    m.fallen = true
    b:update(14.0, m)
    a:update(14.0, me(-1.0, nil))
    assert.is_true(a:mates(14.0)[1].fallen)
    b:update(14.6, me(-3.0, nil))
    a:update(14.6, me(-1.0, nil))
    assert.is_false(a:mates(14.6)[1].fallen)
  end)

  it('reads a flood in bounded steps and keeps a fixed table', function()
    for k = 1, 200 do
      local m = message.encode({ player_id = 1 + k % 11, team = 'blue', pose = { k, 0, 0 } })
      assert(tx:send(m, '127.255.255.255', PORT))
    end
    local r0 = a.received + a.own
    a:update(12.0, me(-1.0, nil))
    assert.is_true(a.received + a.own - r0 <= rules.team.max_per_step)
    for k = 1, 10 do a:update(12.0 + k * 0.01, me(-1.0, nil)) end
    assert.are.equal(rules.team.max_players, #a.slots)
    assert.is_true(#a:mates(12.1) <= rules.team.max_players - 1)
  end)

  it('forgets a teammate not heard for lost_after seconds', function()
    local t = 20.0
    b:update(t, me(-3.0, nil))
    a:update(t, me(-1.0, nil))
    local heard = false
    for _, s in ipairs(a:mates(t)) do if s.player == 2 then heard = true end end
    assert.is_true(heard)
    for _, s in ipairs(a:mates(t + rules.team.lost_after + 0.1)) do assert.are_not.equal(2, s.player) end
  end)

  it('gives the behavior\'s world model its teammates and publishes them in the team block', function()
    local sensor, vision = shm.open('dcm.sensor'), shm.open('vision')
    sensor.time[0], sensor.tick[0] = 50, 0
    local port = PORT + 1
    local behavior = require('Behavior.behavior').new({ port = 0, team_port = port, fresh = true })
    local mate = robot(3, port)
    for k = 1, 50 do
      sensor.tick[0] = 3 * k
      sensor.time[0] = 50 + 0.024 * k
      vision.frame[0] = k
      mate:update(sensor.time[0], me(-2.5, { 1.0, 1.0, 0, 0 }))
      behavior:step()
    end
    local t = shm.open('team')
    assert.are.equal(1, #behavior.world.mates)
    assert.are.equal(3, behavior.world.mates[1].player)
    assert.are.equal(1, t.fresh[2])
    assert.are.equal(-2.5, t.pose[6])
    assert.are.equal(1, t.ball_known[2])
    assert.are.equal(1.0, t.ball[8])
    assert.is_true(t.sent[0] >= 2)
    assert.are.equal(behavior.team.received, t.received[0])
    mate:close()
    behavior:close()
  end)
end)
