-- Fuzz target (Tests/fuzz/lua_fuzz.lua; Tests/team/teamcomm_fuzz_test.sh) of teammates' messages as
-- the robot reads them: Team.team's receive (Team.message's decode through Modules/teamcomm) on
-- one team (player 2, red) across the run. Checks: no Lua error escapes; a datagram is counted
-- exactly once (received, foreign, own or malformed); only a taken message changes a slot, and only
-- the sender's; every slot holds finite numbers (a teammate's pose and ball feed the roles and the
-- world model); the table keeps max_players slots.
local message = require('Team.message')
local Team = require('Team.team')
local Config = require('Config')

local rules = Config.load('game')
local M = { cover = { 'Player/Team/' } }
M.dictionary = { '\8\2', '\8\3', '\16\1', '\16\2', '\21\0\0\192\127', '\21\0\0\128\127', '\255\255\255\255\15' }

function M.seeds()
  local s = {}
  for player = 1, 4 do
    s[#s + 1] = message.encode({ stamp = { 1700000000, 5 }, player_id = player, team = player == 4 and 'blue' or 'red',
      pose = { 1.5 * player, -0.5, 0.3 }, ball = player % 2 == 0 and { 2, 1, 0 } or nil,
      ball_velocity = { 0.1, 0, 0 }, walk = { 0.1, 0, 0.2 }, state = player == 3 and 'penalised' or 'unpenalised',
      others = player == 1 and { { player_id = 2, team = 'red', pose = { 0, 0, 0 } } } or nil,
      target = player == 2 and { player_id = 2, pose = { 1, 1, 0 } } or nil, kick_target = { 4.5, 0 } })
  end
  return s
end

local function fail(fmt, ...) error(string.format(fmt, ...), 0) end
local function finite(x) return type(x) == 'number' and x == x and x > -math.huge and x < math.huge end

local team = Team.new({ team_number = 7, player_number = 2, team = rules.team }, { socket = false })
team.colour = 1 -- red (the GameController's fieldPlayerColour)
local t = 0

local function copy_slot(s)
  return { t = s.t, pose = { unpack(s.pose) }, ball = { unpack(s.ball) }, ball_known = s.ball_known,
    penalised = s.penalised }
end
local function same_slot(a, b)
  if a.t ~= b.t or a.ball_known ~= b.ball_known or a.penalised ~= b.penalised then return false end
  for i = 1, 3 do if a.pose[i] ~= b.pose[i] then return false end end
  for i = 1, 4 do if a.ball[i] ~= b.ball[i] then return false end end
  return true
end
local function total() return team.received + team.foreign + team.own + team.malformed end

function M.run(data)
  t = t + 0.01
  local before = {}
  for k, s in ipairs(team.slots) do before[k] = copy_slot(s) end
  local n0, received = total(), team.received
  local took = team:receive(data, t)
  if total() - n0 ~= 1 then fail('counted %d times', total() - n0) end
  if took ~= (team.received - received == 1) then fail('receive said %s', tostring(took)) end
  if #team.slots ~= rules.team.max_players then fail('%d slots', #team.slots) end
  local m = took and message.decode(data)
  for k, s in ipairs(team.slots) do
    if not (took and m.player_id == k) and not same_slot(s, before[k]) then
      fail('slot %d changed by a message %s', k, took and ('of player ' .. m.player_id) or 'not taken')
    end
    for i = 1, 3 do if not finite(s.pose[i]) then fail('slot %d pose[%d] = %s', k, i, tostring(s.pose[i])) end end
    for i = 1, 4 do if not finite(s.ball[i]) then fail('slot %d ball[%d] = %s', k, i, tostring(s.ball[i])) end end
  end
end

return M
