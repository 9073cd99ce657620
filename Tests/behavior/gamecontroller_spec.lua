-- luacheck: std +busted
-- GameController packets (HL layout, version 12) and the controller the robot follows.
local packet = require('GameFSM.packet')
local controller = require('GameFSM.controller')

local cfg = { team_number = 7, player_number = 2, gamecontroller = { port = 0, start_delay = 2.0 } }

local function gc_packet(state, penalty, extra)
  local p = { state = state, packet_number = 5, kickoff_team = 7,
    teams = { { number = 7, score = 2, players = { {}, { penalty = penalty or 0 } } }, { number = 9, score = 1 } } }
  for k, v in pairs(extra or {}) do p[k] = v end
  return packet.build(p)
end

local function no_socket() return controller.new(cfg, { socket = false }) end

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

  it('rejects truncated, foreign-header, wrong-version and oversized packets', function()
    local s = gc_packet(3)
    assert.are.same({ nil, 'short' }, { packet.parse(s:sub(1, 687)) })
    assert.are.same({ nil, 'short' }, { packet.parse('') })
    assert.are.same({ nil, 'header' }, { packet.parse('XXXX' .. s:sub(5)) })
    assert.are.same({ nil, 'version' }, { packet.parse(s:sub(1, 4) .. '\11\0' .. s:sub(7)) })
    assert.are.same({ nil, 'long' }, { packet.parse(s .. 'x') })
    assert.are.same({ nil, 'state' }, { packet.parse(s:sub(1, 9) .. '\9' .. s:sub(11)) })
  end)
end)

describe('GameController follower', function()
  it('starts playing after the start delay when no GameController is heard', function()
    local c = no_socket()
    assert.are.equal('initial', (c:update(10.0, false)))
    assert.are.equal('initial', (c:update(11.9, false)))
    assert.are.equal('playing', (c:update(12.0, false)))
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

  it('toggles penalized on each press of the button', function()
    local c = no_socket()
    local _, pen = c:update(0, true)
    assert.is_true(pen)
    _, pen = c:update(0.1, true) -- held: no new toggle
    assert.is_true(pen)
    _, pen = c:update(0.2, false)
    assert.is_true(pen)
    _, pen = c:update(0.3, true)
    assert.is_false(pen)
  end)

  it('receives packets over UDP and survives a flood of garbage', function()
    local udp = require('GameFSM.udp')
    local port = 20000 + (tonumber(os.getenv('ROBOT_ID') or '1') % 20000)
    local c = controller.new(cfg, { port = port })
    assert.is_nil(c.socket_error)
    local tx = assert(udp.sender())
    for k = 1, 50 do assert(tx:send(string.rep(string.char(k), k * 13), '127.0.0.1', port)) end
    assert(tx:send(gc_packet(packet.STATE.set), '127.0.0.1', port))
    local s
    for k = 1, 10 do s = c:update(k * 0.01, false) end
    assert.are.equal('set', s)
    assert.are.equal(50, c.bad_packets)
    assert.are.equal(1, c.packets)
    tx:close()
    c:close()
  end)
end)
