-- luacheck: std +busted
-- Network exposure of the robot's UDP listeners (GameController: Player/GameFSM, team communication:
-- Player/Team): bound to the configured interface, datagrams from hosts not configured ignored
-- unread and counted, and a flood of junk costs no memory beyond a fixed bound. Loopback, ports of
-- this test's own; the second sender address is 127.0.0.2 (all of 127/8 is loopback).
local packet = require('GameFSM.packet')
local controller = require('GameFSM.controller')
local Team = require('Team.team')
local message = require('Team.message')
local udp = require('GameFSM.udp')

local id = tonumber(os.getenv('ROBOT_ID') or '1')
local GC_PORT, TEAM_PORT = 24000 + (id % 20000), 26000 + (id % 20000)
math.randomseed(id)

local function gc_cfg(hosts)
  return { team_number = 7, player_number = 2, gamecontroller = { port = GC_PORT, return_port = GC_PORT + 1,
    alive_period = 1.0, start_without = 'initial', start_delay = 2.0, interface = 'lo', hosts = hosts } }
end
local function gc_packet(state)
  return packet.build({ state = state, packet_number = 1,
    teams = { { number = 7, players = { {}, {} } }, { number = 9 } } })
end
local function junk()
  local n = math.random(0, 6000) -- longer than the 4096-byte buffer too
  local t = {}
  for i = 1, n do t[i] = string.char(math.random(0, 255)) end
  return table.concat(t)
end
local function lua_kb() collectgarbage('collect') collectgarbage('collect') return collectgarbage('count') end
local function rss_kb()
  local f = io.open('/proc/self/status')
  local kb = f and tonumber(f:read('*a'):match('VmRSS:%s*(%d+)')) or 0
  if f then f:close() end
  return kb
end

-- sends `n` junk datagrams to port from tx, calling step() every 50 (the robot's steps go on)
local function flood(tx, port, n, step)
  local pieces = {}
  for k = 1, 64 do pieces[k] = junk() end -- made once: the sender's own garbage stays out of the figure
  for k = 1, n do
    tx:send(pieces[k % 64 + 1], '127.0.0.1', port)
    if k % 50 == 0 then step() end
  end
  for _ = 1, 200 do step() end -- drain
end

describe('UDP exposure', function()
  it('a listener hears only the interface the config names; an unknown one is an error naming it', function()
    local s = assert(udp.listen(GC_PORT + 2, 'lo'))
    assert.equal('lo', s:device())
    s:close()
    local all = assert(udp.listen(GC_PORT + 2, ''))
    assert.equal('', all:device())
    all:close()
    local none, err = udp.listen(GC_PORT + 2, 'nosuchif0')
    assert.is_nil(none)
    assert.truthy(err:find("interface 'nosuchif0'", 1, true), err)
    local c = controller.new(gc_cfg({}))
    assert.equal('lo', c.sock:device())
    c:close()
    assert.has_error(function() controller.new(gc_cfg({ 'gc.local' })) end,
      'game.lua gamecontroller.hosts: element 1 must be an IPv4 address like "10.0.0.1", not gc.local')
  end)

  it('the GameController listener ignores and counts other hosts, survives a junk flood in bounded memory', function()
    local c = controller.new(gc_cfg({ '127.0.0.1' }))
    assert.is_nil(c.socket_error)
    local stranger = assert(udp.sender('127.0.0.2'))
    local tx = assert(udp.sender('127.0.0.1'))
    local t = 0
    local function step() t = t + 0.01 c:update(t, false) end
    for _ = 1, 5 do assert(stranger:send(gc_packet(packet.STATE.playing), '127.0.0.1', GC_PORT)) end
    step()
    assert.equal(5, c.rejected)
    assert.equal(0, c.packets)
    assert.equal('initial', (c:update(t, false)))
    -- a flood from the allowed host: every datagram read is counted as bad, memory stays put
    flood(tx, GC_PORT, 500, step)
    local kb0, rss0 = lua_kb(), rss_kb()
    local bad0 = c.bad_packets
    flood(tx, GC_PORT, 20000, step)
    local kb1, rss1 = lua_kb(), rss_kb()
    print(string.format('# GameController flood: %d junk datagrams read (of 20000 sent; the rest dropped by the ' ..
      'kernel queue), Lua heap %+.1f KB, RSS %+d KB', c.bad_packets - bad0, kb1 - kb0, rss1 - rss0))
    assert.is_true(c.bad_packets - bad0 > 1000)
    assert.is_true(kb1 - kb0 < 64, string.format('Lua heap grew %.1f KB', kb1 - kb0))
    -- and the real GameController still gets through
    assert(tx:send(gc_packet(packet.STATE.ready), '127.0.0.1', GC_PORT))
    step()
    assert.equal(1, c.packets)
    assert.equal('ready', (c:update(t, false)))
    stranger:close() tx:close() c:close()
  end)

  it('the team listener ignores and counts other hosts and teams, survives a junk flood in bounded memory', function()
    local tc = { port_base = 0, broadcast = '127.255.255.255', period = 0.5, lost_after = 3.0, max_per_step = 32,
      max_players = 11, interface = 'lo', hosts = { '127.0.0.1' } }
    local team = Team.new({ team_number = TEAM_PORT, player_number = 1, team = tc })
    assert.is_nil(team.socket_error)
    assert.equal('lo', team.sock:device())
    local stranger = assert(udp.sender('127.0.0.2'))
    local tx = assert(udp.sender('127.0.0.1'))
    local me = { pose = { 0, 0, 0 }, penalised = false, colour = 0, walk = { 0, 0, 0 } }
    local t = 0
    local function step() t = t + 0.01 team:update(t, me) end
    local mate = message.encode({ player_id = 2, team = 'blue', pose = { 1, 2, 0 } })
    local foe = message.encode({ player_id = 3, team = 'red', pose = { 1, 2, 0 } })
    for _ = 1, 5 do assert(stranger:send(mate, '127.0.0.1', TEAM_PORT)) end
    assert(tx:send(foe, '127.0.0.1', TEAM_PORT))
    assert(tx:send(mate, '127.0.0.1', TEAM_PORT))
    step()
    assert.equal(5, team.rejected)
    assert.equal(1, team.foreign)
    assert.equal(1, team.received)
    flood(tx, TEAM_PORT, 500, step)
    local kb0, rss0 = lua_kb(), rss_kb()
    local bad0 = team.malformed
    flood(tx, TEAM_PORT, 20000, step)
    local kb1, rss1 = lua_kb(), rss_kb()
    print(string.format('# team flood: %d junk datagrams read (of 20000 sent), Lua heap %+.1f KB, RSS %+d KB',
      team.malformed - bad0, kb1 - kb0, rss1 - rss0))
    assert.is_true(team.malformed - bad0 > 1000)
    assert.is_true(kb1 - kb0 < 64, string.format('Lua heap grew %.1f KB', kb1 - kb0))
    assert.equal(11, #team.slots)
    stranger:close() tx:close() team:close()
  end)
end)
