-- The Lua side of the protobuf cross-check (Tests/team/proto_crosscheck.py):
--   luajit Tests/team/proto_lua.lua decode FILE   prints the decoded message, one "key value..." a line
--   luajit Tests/team/proto_lua.lua encode FILE   writes the message below, encoded by our encoder
local message = require('Team.message')

local mode, file = arg[1], arg[2]
assert((mode == 'decode' or mode == 'encode') and file, 'usage: proto_lua.lua decode|encode FILE')

local function line(key, list)
  local parts = { key }
  for _, v in ipairs(list) do parts[#parts + 1] = string.format('%.9g', v) end
  print(table.concat(parts, ' '))
end

if mode == 'decode' then
  local f = assert(io.open(file, 'rb'))
  local bytes = f:read('*a')
  f:close()
  local m = assert(message.decode(bytes))
  line('player_id', { m.player_id })
  print('team ' .. m.team)
  line('pose', m.pose)
  line('covariance', m.covariance or {})
  line('stamp', m.stamp)
  line('ball', m.ball)
  line('ball_velocity', m.ball_velocity)
  line('ball_covariance', m.ball_covariance or {})
  line('others_total', { m.others_total })
  for i, o in ipairs(m.others) do
    local pose = o.pose or { 0, 0 }
    line('other' .. i, { o.player_id, message.TEAM[o.team], pose[1], pose[2] })
  end
  line('walk', m.walk)
  line('target', m.target.pose)
  line('kick_target', m.kick_target)
  print('state ' .. m.state)
  print('fallen ' .. tostring(m.fallen))
else
  local bytes = message.encode({
    stamp = { 1732400000, 123456789 }, player_id = 4, team = 'blue', pose = { -2.5, 1.25, -1.5 },
    covariance = { 0.04, 0, 0, 0, 0.04, 0, 0, 0, 0.01 },
    ball = { 0.75, -0.5, 0 }, ball_velocity = { 0.5, 0.25, 0 },
    others = { { player_id = 0, team = 'red', pose = { 1, 2, 0 } },
      { player_id = 2, team = 'blue', pose = { -1, 0, 3 } } },
    walk = { 0.2, -0.05, 0.3 }, target = { pose = { 0, 0, 0 } }, kick_target = { 4.5, 0 }, state = 'penalised',
    fallen = true,
  })
  local f = assert(io.open(file, 'wb'))
  f:write(bytes)
  f:close()
end
