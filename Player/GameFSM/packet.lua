-- RoboCup GameController packets, Humanoid League layout (RoboCupGameControlData, header "RGme",
-- version 12, as sent by the HL GameController on UDP port 3838). Little-endian, no padding:
--
--   off size field                      off size TeamInfo (332 bytes)      RobotInfo (6 bytes)
--     0   4 header "RGme"                 0  1 teamNumber                  0 penalty
--     4   2 version (12)                  1  1 fieldPlayerColour           1 secsTillUnpenalised
--     6   1 packetNumber                  2  1 score                       2 numberOfWarnings
--     7   1 playersPerTeam                3  1 penaltyShot                 3 yellowCardCount
--     8   1 gameType                      4  2 singleShots                 4 redCardCount
--     9   1 state                         6  1 coachSequence               5 goalKeeper
--    10   1 firstHalf                     7 253 coachMessage
--    11   1 kickOffTeam                 260  6 coach (RobotInfo)
--    12   1 secondaryState              266 66 players[11] (RobotInfo)
--    13   4 secondaryStateInfo
--    17   1 dropInTeam
--    18   2 dropInTime
--    20   2 secsRemaining
--    22   2 secondaryTime
--    24 664 teams[2]                    total 688 bytes
--
-- parse(bytes) checks length, header and version and returns a plain table, or nil and why.
-- build(t) makes a packet from such a table (tests, a stand-in GameController).
--
-- The robot's answer, RoboCupGameControlReturnData of the HL (header "RGrt", version 2, to the
-- GameController's UDP port 3939), 8 bytes: header[4], version u8, team u8, player u8, message u8
-- (0 manual penalise, 1 manual unpenalise, 2 alive). build_return / parse_return.
-- secondaryStateInfo: [0] the team the set play is for, [1] its mode (0 preparation, 1 placing,
-- 2 end: the referee's "execute").
local M = {}

M.HEADER = 'RGme'
M.VERSION = 12
M.SIZE = 688
M.TEAM_SIZE = 332
M.MAX_PLAYERS = 11
M.COACH_MESSAGE_SIZE = 253
M.PORT = 3838
M.STATES = { [0] = 'initial', 'ready', 'set', 'playing', 'finished' }
M.STATE = { initial = 0, ready = 1, set = 2, playing = 3, finished = 4 }
M.PENALTY_NONE = 0
-- secondaryState (STATE2_*)
M.SECONDARY = { [0] = 'normal', 'penalty_shootout', 'overtime', 'timeout', 'direct_free_kick',
  'indirect_free_kick', 'penalty_kick', 'corner_kick', 'goal_kick', 'throw_in' }
M.MODES = { [0] = 'preparation', 'placing', 'end' }
M.SET_PLAY_FIRST = 4 -- secondary states from direct_free_kick on are set plays: info[2] is their mode
M.RETURN_HEADER = 'RGrt'
M.RETURN_VERSION = 2
M.RETURN_SIZE = 8
M.RETURN_PORT = 3939
M.MSG = { man_penalise = 0, man_unpenalise = 1, alive = 2 }
M.SUBSTITUTE = 14
M.DROPBALL = 255

local byte, char = string.byte, string.char

local function u16(s, off) local a, b = byte(s, off + 1, off + 2) return a + 256 * b end
local function i16(s, off) local v = u16(s, off) if v >= 32768 then v = v - 65536 end return v end
local function u8(s, off) return byte(s, off + 1) end

local function robot_info(s, off)
  return {
    penalty = u8(s, off), secs_till_unpenalised = u8(s, off + 1), warnings = u8(s, off + 2),
    yellow_cards = u8(s, off + 3), red_cards = u8(s, off + 4), goalkeeper = u8(s, off + 5),
  }
end

-- Parses one datagram; returns a table or nil and a reason ('short', 'header', 'version', 'long',
-- 'state', 'secondary_state', 'secondary_mode': a value the protocol does not define, refused
-- rather than read as something else).
function M.parse(s)
  if type(s) ~= 'string' then return nil, 'type' end
  if #s < M.SIZE then return nil, 'short' end
  if s:sub(1, 4) ~= M.HEADER then return nil, 'header' end
  if u16(s, 4) ~= M.VERSION then return nil, 'version' end
  if #s ~= M.SIZE then return nil, 'long' end
  local p = {
    version = u16(s, 4), packet_number = u8(s, 6), players_per_team = u8(s, 7), game_type = u8(s, 8),
    state = u8(s, 9), first_half = u8(s, 10), kickoff_team = u8(s, 11), secondary_state = u8(s, 12),
    secondary_state_info = { u8(s, 13), u8(s, 14), u8(s, 15), u8(s, 16) },
    drop_in_team = u8(s, 17), drop_in_time = u16(s, 18), secs_remaining = i16(s, 20),
    secondary_time = i16(s, 22), teams = {},
  }
  if p.state > 4 then return nil, 'state' end
  if p.secondary_state > #M.SECONDARY then return nil, 'secondary_state' end
  if p.secondary_state >= M.SET_PLAY_FIRST and p.secondary_state_info[2] > #M.MODES then
    return nil, 'secondary_mode'
  end
  for t = 1, 2 do
    local base = 24 + (t - 1) * M.TEAM_SIZE
    local team = {
      number = u8(s, base), colour = u8(s, base + 1), score = u8(s, base + 2),
      penalty_shot = u8(s, base + 3), single_shots = u16(s, base + 4),
      coach = robot_info(s, base + 260), players = {},
    }
    for k = 1, M.MAX_PLAYERS do team.players[k] = robot_info(s, base + 266 + (k - 1) * 6) end
    p.teams[t] = team
  end
  return p
end

-- This robot's view of a parsed packet: state, penalized, our team's index (1/2), colour, scores;
-- nil if the packet does not name our team.
function M.for_robot(p, team_number, player_number)
  for t = 1, 2 do
    if p.teams[t].number == team_number then
      local other = p.teams[3 - t]
      local me = p.teams[t].players[player_number]
      local penalty = me and me.penalty or 0
      local info = p.secondary_state_info
      local keeper = 0
      for k = M.MAX_PLAYERS, 1, -1 do if p.teams[t].players[k].goalkeeper ~= 0 then keeper = k end end
      return {
        state = p.state, penalty = penalty, penalized = penalty ~= M.PENALTY_NONE,
        team_colour = p.teams[t].colour, kickoff_team = p.kickoff_team,
        our_kickoff = p.kickoff_team == team_number, score = { p.teams[t].score, other.score },
        secondary_state = p.secondary_state, first_half = p.first_half,
        secondary_team = info[1], secondary_mode = info[2], secondary_time = p.secondary_time,
        secs_remaining = p.secs_remaining, goalkeeper = (me and me.goalkeeper or 0) ~= 0,
        goalkeeper_player = keeper,
      }
    end
  end
  return nil
end

local function put_u16(v) v = v % 65536 return char(v % 256, math.floor(v / 256)) end

local function put_robot(r)
  r = r or {}
  return char(r.penalty or 0, r.secs_till_unpenalised or 0, r.warnings or 0, r.yellow_cards or 0,
    r.red_cards or 0, r.goalkeeper or 0)
end

-- Builds a packet from a table shaped like parse()'s result (missing fields are zero).
function M.build(p)
  local parts = {
    M.HEADER, put_u16(p.version or M.VERSION),
    char(p.packet_number or 0, p.players_per_team or 4, p.game_type or 0, p.state or 0, p.first_half or 1,
      p.kickoff_team or 0, p.secondary_state or 0),
    char(unpack(p.secondary_state_info or { 0, 0, 0, 0 })),
    char(p.drop_in_team or 0), put_u16(p.drop_in_time or 0xffff),
    put_u16(p.secs_remaining or 600), put_u16(p.secondary_time or 0),
  }
  for t = 1, 2 do
    local team = (p.teams or {})[t] or {}
    parts[#parts + 1] = char(team.number or 0, team.colour or (t - 1), team.score or 0,
      team.penalty_shot or 0)
    parts[#parts + 1] = put_u16(team.single_shots or 0)
    parts[#parts + 1] = char(0) .. string.rep('\0', M.COACH_MESSAGE_SIZE)
    parts[#parts + 1] = put_robot(team.coach)
    for k = 1, M.MAX_PLAYERS do parts[#parts + 1] = put_robot((team.players or {})[k]) end
  end
  local s = table.concat(parts)
  assert(#s == M.SIZE, 'packet.build: size ' .. #s)
  return s
end

-- The robot's return packet (8 bytes) for `message` (M.MSG).
function M.build_return(team, player, message)
  return M.RETURN_HEADER .. char(M.RETURN_VERSION, team, player, message)
end

-- Parses a return packet: { version, team, player, message } or nil and why.
function M.parse_return(s)
  if type(s) ~= 'string' or #s ~= M.RETURN_SIZE then return nil, 'size' end
  if s:sub(1, 4) ~= M.RETURN_HEADER then return nil, 'header' end
  local v, team, player, message = byte(s, 5, 8)
  if v ~= M.RETURN_VERSION then return nil, 'version' end
  return { version = v, team = team, player = player, message = message }
end

return M
