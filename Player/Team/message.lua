-- The Humanoid League's team message (robocup.proto) from Lua: plain tables in and out, through
-- Modules/teamcomm (protobuf-c) and the FFI.
--
--   local message = require('Team.message')
--   local bytes = message.encode({ player_id = 2, team = 'red', pose = { x, y, a }, ball = { x, y },
--     ball_velocity = { vx, vy }, state = 'unpenalised', fallen = false, walk = { vx, vy, va }, stamp = { s, ns } })
--   local m, err = message.decode(bytes)   -- the same shape (absent parts nil); nil, err if malformed
local ffi = require('ffi')
local native = require('native')

ffi.cdef [[
typedef struct {
  uint32_t player_id; int32_t team; int32_t has_position; float position[3];
  int32_t has_covariance; float covariance[9];
} tc_robot;
typedef struct {
  int32_t has_timestamp; int64_t seconds; int32_t nanos;
  int32_t has_pose; tc_robot pose;
  int32_t has_ball; float ball[3]; float ball_velocity[3];
  int32_t has_ball_covariance; float ball_covariance[9];
  uint32_t n_others; uint32_t others_total; tc_robot others[16];
  int32_t has_walk_command; float walk_command[3];
  int32_t has_target_pose; tc_robot target_pose;
  int32_t has_kick_target; float kick_target[2];
  int32_t state;
  int32_t fallen;
} tc_message;
int tc_encode(const tc_message *m, uint8_t *buf, size_t cap, char *err, size_t errlen);
int tc_decode(const uint8_t *buf, size_t len, tc_message *m, char *err, size_t errlen);
size_t tc_message_size(void);
]]

local lib = native.load('team')
assert(tonumber(lib.tc_message_size()) == ffi.sizeof('tc_message'),
  'Team.message: tc_message in Modules/teamcomm/teamcomm.h and this file differ')

local M = {}
M.MAX_SIZE = 2048
M.MAX_OTHERS = 16
M.TEAMS = { [0] = 'unknown', 'blue', 'red' }
M.TEAM = { unknown = 0, blue = 1, red = 2 }
M.STATES = { [0] = 'unknown', 'unpenalised', 'penalised' }
M.STATE = { unknown = 0, unpenalised = 1, penalised = 2 }

-- buffers made once: encoding and decoding make no garbage beyond the strings and tables returned
local msg = ffi.new('tc_message')
local buf = ffi.new('uint8_t[?]', M.MAX_SIZE)
local err = ffi.new('char[160]')

local function put_robot(r, t)
  r.player_id = t.player_id or 0
  r.team = M.TEAM[t.team or 'unknown'] or error("Team.message: unknown team '" .. tostring(t.team) .. "'", 3)
  if t.pose then
    r.has_position = 1
    r.position[0], r.position[1], r.position[2] = t.pose[1], t.pose[2], t.pose[3] or 0
  end
  if t.covariance then
    r.has_covariance = 1
    for i = 1, 9 do r.covariance[i - 1] = t.covariance[i] end
  end
end

local function get_robot(r)
  local t = { player_id = r.player_id, team = M.TEAMS[r.team] or r.team }
  if r.has_position ~= 0 then t.pose = { r.position[0], r.position[1], r.position[2] } end
  if r.has_covariance ~= 0 then
    t.covariance = {}
    for i = 1, 9 do t.covariance[i] = r.covariance[i - 1] end
  end
  return t
end

-- Encodes a table (the shape above; `others`: a list of robots, `target`: a robot,
-- `kick_target`: {x, y}); the message's bytes.
function M.encode(t)
  ffi.fill(msg, ffi.sizeof(msg))
  if t.stamp then msg.has_timestamp, msg.seconds, msg.nanos = 1, t.stamp[1], t.stamp[2] or 0 end
  msg.has_pose = 1
  put_robot(msg.pose, t)
  if t.ball then
    msg.has_ball = 1
    msg.ball[0], msg.ball[1], msg.ball[2] = t.ball[1], t.ball[2], t.ball[3] or 0
    local v = t.ball_velocity or {}
    msg.ball_velocity[0], msg.ball_velocity[1], msg.ball_velocity[2] = v[1] or 0, v[2] or 0, v[3] or 0
    if t.ball_covariance then
      msg.has_ball_covariance = 1
      for i = 1, 9 do msg.ball_covariance[i - 1] = t.ball_covariance[i] end
    end
  end
  local others = t.others or {}
  if #others > M.MAX_OTHERS then error('Team.message: more than 16 others', 2) end
  msg.n_others = #others
  for i, o in ipairs(others) do put_robot(msg.others[i - 1], o) end
  if t.walk then
    msg.has_walk_command = 1
    msg.walk_command[0], msg.walk_command[1], msg.walk_command[2] = t.walk[1], t.walk[2], t.walk[3]
  end
  if t.target then msg.has_target_pose = 1 put_robot(msg.target_pose, t.target) end
  if t.kick_target then
    msg.has_kick_target = 1
    msg.kick_target[0], msg.kick_target[1] = t.kick_target[1], t.kick_target[2]
  end
  msg.fallen = t.fallen and 1 or 0
  msg.state = M.STATE[t.state or 'unknown'] or error("Team.message: unknown state '" .. tostring(t.state) .. "'", 2)
  local n = lib.tc_encode(msg, buf, M.MAX_SIZE, err, 160)
  if n < 0 then error(ffi.string(err), 2) end
  return ffi.string(buf, n)
end

-- Decodes bytes; a table, or nil and why (too long, not a message).
function M.decode(s)
  if #s > M.MAX_SIZE then return nil, 'longer than ' .. M.MAX_SIZE .. ' bytes' end
  if lib.tc_decode(s, #s, msg, err, 160) ~= 0 then return nil, ffi.string(err) end
  local t = msg.has_pose ~= 0 and get_robot(msg.pose) or { player_id = 0, team = 'unknown' }
  t.has_pose = msg.has_pose ~= 0
  if msg.has_timestamp ~= 0 then t.stamp = { tonumber(msg.seconds), msg.nanos } end
  if msg.has_ball ~= 0 then
    t.ball = { msg.ball[0], msg.ball[1], msg.ball[2] }
    t.ball_velocity = { msg.ball_velocity[0], msg.ball_velocity[1], msg.ball_velocity[2] }
    if msg.has_ball_covariance ~= 0 then
      t.ball_covariance = {}
      for i = 1, 9 do t.ball_covariance[i] = msg.ball_covariance[i - 1] end
    end
  end
  t.others, t.others_total = {}, msg.others_total
  for i = 1, msg.n_others do t.others[i] = get_robot(msg.others[i - 1]) end
  if msg.has_walk_command ~= 0 then t.walk = { msg.walk_command[0], msg.walk_command[1], msg.walk_command[2] } end
  if msg.has_target_pose ~= 0 then t.target = get_robot(msg.target_pose) end
  if msg.has_kick_target ~= 0 then t.kick_target = { msg.kick_target[0], msg.kick_target[1] } end
  t.state = M.STATES[msg.state] or msg.state
  t.fallen = msg.fallen ~= 0
  return t
end

return M
