-- Fuzz target (Tests/fuzz/lua_fuzz.lua; Tests/game/gc_fuzz_test.sh) of the GameController packets as
-- the robot reads them: Player/GameFSM/packet.lua's parse and parse_return, and a controller
-- (GameFSM.controller, team 7 player 2) fed each input as a datagram through its update(). Checks,
-- against the layout read here independently: no Lua error escapes; a datagram is counted exactly
-- once, as a packet if it is a well-formed packet naming our team and as a bad packet otherwise; a
-- bad packet changes nothing but the counters; the game view and the set-play rules accept every
-- packet taken; a parsed packet rebuilds to the same table; a return packet rebuilds to its bytes.
local packet = require('GameFSM.packet')
local controller = require('GameFSM.controller')
local setplay = require('GameFSM.setplay')
local Config = require('Config')

local TEAM, PLAYER = 7, 2
local rules = Config.load('game')
local byte = string.byte

local M = { cover = { 'Player/GameFSM/' } }
M.dictionary = { packet.HEADER, packet.RETURN_HEADER, '\12\0', string.char(TEAM), '\2', '\3', '\4', '\9',
  '\255' }

-- valid packets from the real layout: every state and set play, our team first or second, penalties
function M.seeds()
  local seeds = {}
  for state = 0, 4 do
    for sec = 0, 9 do
      local ours = sec % 2 == 0
      seeds[#seeds + 1] = packet.build({
        state = state, packet_number = state * 10 + sec, secondary_state = sec, kickoff_team = ours and TEAM or 3,
        secondary_state_info = { ours and TEAM or 3, sec % 3, 0, 0 }, secs_remaining = 600 - 37 * sec,
        secondary_time = sec - 3,
        teams = ours and {
          { number = TEAM, colour = 1, score = state, players = { [PLAYER] = { penalty = sec % 4, goalkeeper = 1 } } },
          { number = 3, score = sec } }
          or { { number = 3 }, { number = TEAM, players = { { goalkeeper = 1 }, { penalty = 14 } } } },
      })
    end
  end
  seeds[#seeds + 1] = packet.build({ teams = { { number = 1 }, { number = 2 } } }) -- another game's
  seeds[#seeds + 1] = packet.build_return(TEAM, PLAYER, packet.MSG.alive)
  seeds[#seeds + 1] = packet.build_return(TEAM, PLAYER, packet.MSG.man_penalise)
  return seeds
end

local function fail(fmt, ...) error(string.format(fmt, ...), 0) end

-- the reference: is `s` a packet the robot must take (the HL layout, version 12, states and
-- secondary states in range, a set play's mode in range, our team in it)?
local function u16(s, off) return byte(s, off + 1) + 256 * byte(s, off + 2) end
local function well_formed(s)
  if #s ~= packet.SIZE or s:sub(1, 4) ~= 'RGme' or u16(s, 4) ~= 12 then return false end
  local state, sec, mode = byte(s, 10), byte(s, 13), byte(s, 15)
  return state <= 4 and sec <= 9 and (sec < 4 or mode <= 2)
end
local function expected(s)
  return well_formed(s) and (byte(s, 25) == TEAM or byte(s, 25 + packet.TEAM_SIZE) == TEAM)
end

local function deep_equal(a, b, path)
  if type(a) ~= type(b) then fail('%s: %s vs %s', path, tostring(a), tostring(b)) end
  if type(a) ~= 'table' then
    if a ~= b then fail('%s: %s vs %s', path, tostring(a), tostring(b)) end
    return
  end
  for k, v in pairs(a) do deep_equal(v, b[k], path .. '.' .. tostring(k)) end
  for k in pairs(b) do if a[k] == nil then fail('%s.%s: only in one', path, tostring(k)) end end
end

-- what a bad packet must leave alone: every field but the counters and the clock
local COUNTERS = { bad_packets = true, foreign_packets = true, t_last = true, t_start = true,
  last_alive = true, returns = true }
local function snapshot(gc)
  local s = {}
  for k, v in pairs(gc) do
    if not COUNTERS[k] and type(v) ~= 'function' and k ~= 'sock' and k ~= 'sent' and k ~= 'cfg' then
      s[k] = type(v) == 'table' and { unpack(v) } or v
    end
  end
  return s
end

-- one controller across the run: state carried from packet to packet, as on the robot
local queue = {}
local fake_socket = { receive = function() return table.remove(queue, 1), '10.0.0.2' end,
  send = function() return true end, close = function() end }
-- start_without 'initial': only packets change the state (the sim's config starts playing on its own)
local gcfg = setmetatable({ start_without = 'initial' }, { __index = rules.gamecontroller })
local gc = controller.new({ team_number = TEAM, player_number = PLAYER, gamecontroller = gcfg },
  { socket = false, sent = {} })
gc.sock = fake_socket
local t = 0

local SECONDARY_NAMES, MODE_NAMES = {}, {}
for _, v in pairs(packet.SECONDARY) do SECONDARY_NAMES[v] = true end
for _, v in pairs(packet.MODES) do MODE_NAMES[v] = true end

local function check_view()
  local v = gc:view()
  if not SECONDARY_NAMES[v.secondary] then fail('view: secondary %s', tostring(v.secondary)) end
  if v.secondary_mode ~= nil and not MODE_NAMES[v.secondary_mode] then
    fail('view: secondary_mode %s', tostring(v.secondary_mode))
  end
  for _, role in ipairs({ 'goalkeeper', 'striker', 'defender' }) do
    for _, kickoff in ipairs({ { since = 0, ball_moved = false }, { since = 20, ball_moved = true } }) do
      local mode = setplay.decide(v, rules, kickoff, role)
      if not setplay.INDEX[mode] then fail('setplay.decide: %s', tostring(mode)) end
    end
  end
end

local REASONS = { short = true, header = true, version = true, long = true, state = true,
  secondary_state = true, secondary_mode = true }

function M.run(s)
  -- the parser alone
  local p, why = packet.parse(s)
  if (p ~= nil) ~= well_formed(s) then
    fail('parse %s a packet the reference %s', p and 'took' or 'refused', p and 'refuses' or 'takes')
  end
  if p then deep_equal(packet.parse(packet.build(p)), p, 'rebuilt')
  elseif not REASONS[why] then fail('parse: reason %s', tostring(why)) end
  local r = packet.parse_return(s)
  if r and packet.build_return(r.team, r.player, r.message) ~= s then fail('return packet does not rebuild') end
  -- the controller, as the behavior steps it
  local before, packets, bad = snapshot(gc), gc.packets, gc.bad_packets
  queue[1] = s
  t = t + 0.01
  gc.sent = {}
  local state, penalized = gc:update(t, false)
  if #queue ~= 0 then fail('the datagram was not read') end
  local took = gc.packets - packets
  if took + gc.bad_packets - bad ~= 1 then fail('counted %d times', took + gc.bad_packets - bad) end
  if (took == 1) ~= expected(s) then
    fail('%s a packet the reference %s', took == 1 and 'took' or 'refused', expected(s) and 'takes' or 'refuses')
  end
  if took == 0 then
    local after = snapshot(gc)
    for k in pairs(after) do deep_equal(after[k], before[k], 'after a bad packet: ' .. k) end
  elseif gc.state ~= byte(s, 10) or state ~= packet.STATES[byte(s, 10)] then
    fail('state %s after a packet with state %d', tostring(state), byte(s, 10))
  end
  if type(penalized) ~= 'boolean' then fail('penalized is %s', tostring(penalized)) end
  check_view()
end

return M
