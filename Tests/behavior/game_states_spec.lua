-- luacheck: std +busted
-- The behavior follows the game states sent by a GameController (packets built here, sent over UDP):
-- initial, ready, set, playing, penalized and back. The robot's clock and vision frames are driven
-- by the test (no simulator needed); what the behavior asks of the walk is read from the motion block.
local shm = require('shm')
local view = require('Tests.behavior.view')
local packet = require('GameFSM.packet')
local udp = require('GameFSM.udp')

describe('behavior under a GameController', function()
  local port = 30000 + (tonumber(os.getenv('ROBOT_ID') or '1') % 20000)
  local behavior, sensor, vision, motion, game, tx
  local tick = 0

  setup(function()
    sensor, vision = shm.open('dcm.sensor'), shm.open('vision')
    motion, game = shm.open('motion'), shm.open('game')
    sensor.time[0], sensor.tick[0] = 100, 0
    behavior = require('Behavior.behavior').new({ port = port, return_port = port + 1, team_port = port + 2 })
    tx = assert(udp.sender())
  end)

  teardown(function()
    behavior:close()
    tx:close()
    -- the test robot's blocks only (Tests/run_all.sh gives every run its own ROBOT_ID)
    if os.getenv('ROBOT_ID') then for _, name in ipairs(shm.block_names()) do shm.unlink(name) end end
  end)

  -- advances the clock by `seconds` in behavior steps, with a vision frame per step: the ball 1 m
  -- ahead, and the opponent goal's posts as seen from (-2, 0) facing it (the robot attacks only
  -- once it knows where it is)
  local function run(seconds)
    for _ = 1, math.floor(seconds / 0.024 + 0.5) do
      tick = view.frame(sensor, vision, tick, 1.0, 0.2)
      behavior:step()
    end
  end

  -- our kick-off (team 1): the other team's would hold the robot back (game_rules_spec.lua)
  local function send(state, penalty)
    assert(tx:send(packet.build({ state = state, packet_number = 1, kickoff_team = 1,
      teams = { { number = 9 }, { number = 1, players = { { penalty = penalty or 0 } } } } }),
      '127.0.0.1', port))
  end

  local function speed()
    return math.abs(motion.velocity[0]) + math.abs(motion.velocity[1]) + math.abs(motion.velocity[2])
  end
  local function body() return behavior.body:state() end

  it('stays in initial (standing) while the GameController says initial', function()
    send(packet.STATE.initial)
    run(5) -- beyond the start-up delay: with a GameController heard, no default start
    assert.are.equal(0, game.state[0])
    assert.are.equal('initial', behavior.game:state())
    assert.are.equal('idle', body())
    assert.are.equal(0, speed())
    assert.are.equal(1, game.packets[0])
  end)

  it('copies each GameController packet it reads, raw, into net.packets for the recorder', function()
    local ring = shm.open('net.packets')
    local before = ring.written[0]
    local data = packet.build({ state = packet.STATE.initial, packet_number = 2, kickoff_team = 1,
      teams = { { number = 9 }, { number = 1 } } })
    assert(tx:send(data, '127.0.0.1', port))
    run(0.1)
    -- the new entries: this packet, and the robot's own team broadcasts heard back (source 2)
    local gc_slots = {}
    for k = before, ring.written[0] - 1 do
      local slot = k % ring:count('source')
      if ring.source[slot] == 1 then gc_slots[#gc_slots + 1] = slot end
    end
    assert.are.equal(1, #gc_slots)
    local slot = gc_slots[1]
    local size = ring:count('data') / ring:count('source')
    assert.are.equal(#data, ring.length[slot])
    assert.are.equal(data, require('ffi').string(ring.data + slot * size, ring.length[slot]))
    assert.are.equal(127 * 2 ^ 24 + 1, ring.host[slot])
    assert.is_true(ring.time[slot] >= 100) -- the robot clock when the behavior read it
  end)

  it('walks to its position in ready', function()
    send(packet.STATE.ready)
    run(1)
    assert.are.equal(1, game.state[0])
    assert.are.equal('ready', behavior.game:state())
    assert.is_true(speed() > 0)
  end)

  it('stands in set', function()
    send(packet.STATE.set)
    run(1)
    assert.are.equal(2, game.state[0])
    assert.are.equal(0, speed())
  end)

  it('plays in playing: the body machine goes for the ball', function()
    send(packet.STATE.playing)
    run(2)
    assert.are.equal(3, game.state[0])
    assert.are_not.equal('idle', body())
    assert.is_true(speed() > 0)
    assert.is_true(game.body_state[0] > 0)
  end)

  it('stands while penalized and plays again when released', function()
    send(packet.STATE.playing, 34) -- HL_PICKUP_OR_INCAPABLE
    run(1)
    assert.are.equal(1, game.penalized[0])
    assert.are.equal('penalized', behavior.game:state())
    assert.are.equal(0, speed())
    send(packet.STATE.playing, 0)
    run(2)
    assert.are.equal(0, game.penalized[0])
    assert.are.equal('playing', behavior.game:state())
    assert.is_true(speed() > 0)
  end)

  it('ignores garbage and other teams\' packets without changing state', function()
    tx:send(string.rep('x', 30), '127.0.0.1', port)
    local foreign = packet.build({ state = packet.STATE.finished, teams = { { number = 4 }, { number = 5 } } })
    tx:send(foreign:sub(1, 600), '127.0.0.1', port)
    tx:send(foreign, '127.0.0.1', port)
    run(0.5)
    assert.are.equal(3, game.state[0])
    assert.are.equal(3, game.bad_packets[0])
  end)

  it('stops when the vision process stops delivering frames', function()
    for _ = 1, 80 do -- 1.9 s of clock with no new frame
      tick = tick + 3
      sensor.tick[0] = tick
      sensor.time[0] = sensor.time[0] + 0.024
      behavior:step()
    end
    assert.are.equal('idle', body())
    assert.are.equal(0, speed())
  end)

  it('finishes standing', function()
    send(packet.STATE.finished)
    run(1)
    assert.are.equal(4, game.state[0])
    assert.are.equal(0, speed())
  end)
end)
