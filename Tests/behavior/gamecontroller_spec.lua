-- luacheck: std +busted
-- GameController packets (HL layout, version 12), the robot's return packets (RGrt version 2) and
-- the controller the robot follows.
local packet = require('GameFSM.packet')
local controller = require('GameFSM.controller')
local udp = require('GameFSM.udp')

local function config(start_without)
  return { team_number = 7, player_number = 2, gamecontroller = { port = 0, return_port = 0,
    alive_period = 1.0, start_without = start_without or 'playing', start_delay = 2.0 } }
end
local cfg = config()

local function gc_packet(state, penalty, extra)
  local p = { state = state, packet_number = 5, kickoff_team = 7,
    teams = { { number = 7, score = 2, players = { {}, { penalty = penalty or 0 } } }, { number = 9, score = 1 } } }
  for k, v in pairs(extra or {}) do p[k] = v end
  return packet.build(p)
end

local function no_socket(c) return controller.new(c or cfg, { socket = false, sent = {} }) end

describe('GameController packet', function()
  it('has the 688-byte HL version 12 layout and round-trips', function()
    local s = gc_packet(packet.STATE.set, 34)
    assert.are.equal(688, #s)
    assert.are.equal('RGme', s:sub(1, 4))
    assert.are.equal(12, s:byte(5) + 256 * s:byte(6))
    assert.are.equal(2, s:byte(10))                -- state at offset 9
    assert.are.equal(7, s:byte(25))                -- teams[0].teamNumber at offset 24
    assert.are.equal(34, s:byte(24 + 266 + 6 + 1)) -- teams[0].players[1].penalty
    assert.are.equal(9, s:byte(24 + 332 + 1))      -- teams[1].teamNumber
    local p = assert(packet.parse(s))
    assert.are.equal(2, p.state)
    assert.are.equal(34, p.teams[1].players[2].penalty)
    local mine = packet.for_robot(p, 7, 2)
    assert.is_true(mine.penalized)
    assert.are.same({ 2, 1 }, mine.score)
    assert.is_nil(packet.for_robot(p, 8, 1))
  end)

  it('reads the set play, its team and mode, the times and the goalkeeper flag', function()
    local s = gc_packet(packet.STATE.playing, 0, { secondary_state = 8, secondary_state_info = { 9, 1, 0, 0 },
      secondary_time = 27, secs_remaining = 412,
      teams = { { number = 7, players = { {}, { goalkeeper = 1 } } }, { number = 9 } } })
    assert.are.equal(8, s:byte(13))                -- secondaryState at offset 12
    assert.are.equal(9, s:byte(14))                -- secondaryStateInfo[0] at 13
    assert.are.equal(1, s:byte(15))                -- secondaryStateInfo[1]
    assert.are.equal(27, s:byte(23))               -- secondaryTime at 22
    assert.are.equal(412, s:byte(21) + 256 * s:byte(22)) -- secsRemaining at 20
    assert.are.equal(1, s:byte(24 + 266 + 6 + 5 + 1)) -- teams[0].players[1].goalKeeper
    local mine = packet.for_robot(assert(packet.parse(s)), 7, 2)
    assert.are.equal('goal_kick', packet.SECONDARY[mine.secondary_state])
    assert.are.equal(9, mine.secondary_team)
    assert.are.equal('placing', packet.MODES[mine.secondary_mode])
    assert.are.equal(27, mine.secondary_time)
    assert.are.equal(412, mine.secs_remaining)
    assert.is_true(mine.goalkeeper)
  end)

  it('builds the 8-byte RGrt version 2 return packet field by field', function()
    local r = packet.build_return(7, 2, packet.MSG.alive)
    assert.are.equal(8, #r)
    assert.are.same({ 82, 71, 114, 116, 2, 7, 2, 2 }, { r:byte(1, 8) }) -- "RGrt", version, team, player, message
    assert.are.same({ version = 2, team = 7, player = 2, message = 2 }, packet.parse_return(r))
    assert.are.same({ 0, 1, 2 }, { packet.MSG.man_penalise, packet.MSG.man_unpenalise, packet.MSG.alive })
    assert.are.same({ nil, 'size' }, { packet.parse_return(r .. 'x') })
    assert.are.same({ nil, 'header' }, { packet.parse_return('RGme' .. r:sub(5)) })
    assert.are.same({ nil, 'version' }, { packet.parse_return('RGrt\1' .. r:sub(6)) })
  end)

  it('rejects truncated, foreign-header, wrong-version and oversized packets', function()
    local s = gc_packet(3)
    assert.are.same({ nil, 'short' }, { packet.parse(s:sub(1, 687)) })
    assert.are.same({ nil, 'short' }, { packet.parse('') })
    assert.are.same({ nil, 'header' }, { packet.parse('XXXX' .. s:sub(5)) })
    assert.are.same({ nil, 'version' }, { packet.parse(s:sub(1, 4) .. '\11\0' .. s:sub(7)) })
    assert.are.same({ nil, 'long' }, { packet.parse(s .. 'x') })
    assert.are.same({ nil, 'state' }, { packet.parse(s:sub(1, 9) .. '\9' .. s:sub(11)) })
  end)

  -- found by Tests/game/gc_fuzz_test.sh: a free kick with mode 255 was taken, its mode read as none
  -- (our set play "taken" forever); a secondary state past throw-in was read as normal play
  it('rejects secondary states and set-play modes the protocol does not define', function()
    local function with(sec, mode)
      return gc_packet(3, 0, { secondary_state = sec, secondary_state_info = { 7, mode, 0, 0 } })
    end
    assert.are.same({ nil, 'secondary_mode' }, { packet.parse(with(4, 255)) })
    assert.are.same({ nil, 'secondary_mode' }, { packet.parse(with(9, 3)) })
    assert.are.same({ nil, 'secondary_state' }, { packet.parse(with(10, 0)) })
    assert.is_table(packet.parse(with(9, 2)))
    assert.is_table(packet.parse(with(3, 200))) -- a timeout's info holds no mode
    local c = no_socket()
    assert.is_false(c:receive(with(4, 255)))
    assert.are.same({ 1, 0 }, { c.bad_packets, c.packets })
  end)
end)

describe('GameController follower', function()
  it('without a GameController, the simulator start plays after the start delay', function()
    local c = no_socket()
    assert.are.equal('initial', (c:update(10.0, false)))
    assert.are.equal('initial', (c:update(11.9, false)))
    assert.are.equal('playing', (c:update(12.0, false)))
    assert.are.equal(0, #c.sent) -- nobody to answer
  end)

  it('without a GameController, the real robot start waits in initial for the button', function()
    local c = no_socket(config('initial'))
    assert.are.equal('initial', (c:update(0, false)))
    assert.are.equal('initial', (c:update(60, false)))
    local s, pen = c:update(60.1, true)
    assert.are.equal('playing', s)
    assert.is_false(pen)
    c:update(60.2, false)
    s, pen = c:update(60.3, true) -- then the button is the referee: a penalty ...
    assert.are.equal('playing', s)
    assert.is_true(pen)
    c:update(60.4, false)
    assert.is_false(select(2, c:update(60.5, true))) -- ... and its end
  end)

  it('without a GameController, the real robot start follows the first packet', function()
    local c = no_socket(config('initial'))
    c:update(0, false)
    assert.is_true(c:receive(gc_packet(packet.STATE.ready), '10.0.0.9'))
    assert.are.equal('ready', (c:update(1, false)))
  end)

  it('follows packets for its team and ignores and counts the rest', function()
    local c = no_socket()
    c:update(0, false)
    assert.is_true(c:receive(gc_packet(packet.STATE.ready)))
    assert.are.equal('ready', (c:update(5, false))) -- a GameController exists: no start-up default
    assert.is_false(c:receive(gc_packet(packet.STATE.playing):sub(1, 100)))
    assert.is_false(c:receive(string.rep('\255', 688)))
    assert.is_false(c:receive(packet.build({ state = 3, teams = { { number = 1 }, { number = 2 } } })))
    assert.are.equal('ready', (c:update(6, false)))
    assert.are.equal(3, c.bad_packets)
    assert.are.equal(1, c.foreign_packets)
    assert.are.equal(1, c.packets)
    c:receive(gc_packet(packet.STATE.playing, 34))
    local s, pen = c:update(7, false)
    assert.are.equal('playing', s)
    assert.is_true(pen)
    c:receive(gc_packet(packet.STATE.playing, 0))
    pen = select(2, c:update(8, false))
    assert.is_false(pen)
    assert.are.same({ 2, 1 }, c.score)
  end)

  it('reports the button to the GameController, whose packets decide the penalty', function()
    local c = no_socket()
    c:receive(gc_packet(packet.STATE.playing, 0), '127.0.0.1')
    c:update(0, false)
    local n = #c.sent -- the first alive
    local s, pen = c:update(0.1, true)
    assert.are.equal('playing', s)
    assert.is_false(pen) -- not by itself: it asked
    assert.are.same({ version = 2, team = 7, player = 2, message = packet.MSG.man_penalise },
      packet.parse_return(c.sent[n + 1]))
    c:update(0.2, true) -- held: asked once
    assert.are.equal(n + 1, #c.sent)
    c:receive(gc_packet(packet.STATE.playing, 34))
    c:update(0.3, false)
    assert.is_true(c:penalized())
    c:update(0.4, true) -- penalized: the button asks to be unpenalised
    assert.are.equal(packet.MSG.man_unpenalise, packet.parse_return(c.sent[n + 2]).message)
    assert.is_true(c:penalized()) -- until the GameController says so
    c:receive(gc_packet(packet.STATE.playing, 0))
    c:update(0.5, false)
    assert.is_false(c:penalized())
  end)

  it('says alive about once a second of robot time once a GameController is heard', function()
    local c = no_socket()
    for k = 0, 50 do c:update(k * 0.1, false) end
    assert.are.equal(0, #c.sent) -- no GameController yet: nobody to answer
    c:receive(gc_packet(packet.STATE.initial), '127.0.0.1')
    for k = 51, 150 do c:update(k * 0.1, false) end -- 10 s
    assert.are.equal(10, #c.sent)
    for _, r in ipairs(c.sent) do
      assert.are.same({ version = 2, team = 7, player = 2, message = packet.MSG.alive }, packet.parse_return(r))
    end
    assert.are.equal(10, c.returns)
  end)

  it('receives packets over UDP, answers the sender on the return port and survives garbage', function()
    local id = tonumber(os.getenv('ROBOT_ID') or '1')
    local port, rport = 20000 + (id % 20000), 40000 + (id % 20000)
    local gc_side = assert(udp.listen(rport))
    local c = controller.new(cfg, { port = port, return_port = rport })
    assert.is_nil(c.socket_error)
    local tx = assert(udp.sender())
    for k = 1, 50 do assert(tx:send(string.rep(string.char(k), k * 13), '127.0.0.1', port)) end
    assert(tx:send(gc_packet(packet.STATE.set), '127.0.0.1', port))
    local s
    for k = 1, 10 do s = c:update(k * 0.01, false) end
    assert.are.equal('set', s)
    assert.are.equal(50, c.bad_packets)
    assert.are.equal(1, c.packets)
    local data, host = gc_side:receive()
    assert.are.equal('127.0.0.1', host)
    assert.are.same({ version = 2, team = 7, player = 2, message = packet.MSG.alive }, packet.parse_return(data))
    assert.is_nil(gc_side:receive()) -- one alive per second
    gc_side:close()
    tx:close()
    c:close()
  end)
end)
