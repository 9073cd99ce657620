-- The fall census: every fall in the sim, classified from the simulator's truth at the moment the torso
-- tips, with the robot's commanded and measured speed there and where on the field (Tools/match/referee.lua,
-- Tests/soak/soak_play.lua). Pure Lua: the caller feeds it one record per robot per look.
--
--   local census = require('Tools.match.census')
--   local c = census.new(params, { 'team 1/1', ... }, field)   -- params: game.lua's referee.census; field (nil:
--                    -- no goals): { length, goal_width, goal_depth } (m, Config sim.lua's field and goal)
--   c:look(i, rec)   -- robot i at rec.t: { t, x, y, yaw, roll, pitch, fallen, state (motion state name),
--                    -- kick (true while a kick out of the walk strikes), cmd = { vx, vy, va } (the walk's
--                    -- command, m/s and rad/s, robot frame), ball = { x, y } or nil, others = { { x, y }, ... }
--                    -- (the other robots' torsos), pushed (true while a push acts) }; returns the fall
--                    -- record when the truth says fallen and the robot had got up (tilt under tip_angle) since
--                    -- its last fall (a robot that rolls about on the ground falls once)
--   c:push(i, t)     -- robot i was pushed at t (a scenario's Sim.push)
--   c.falls          -- the fall records: { robot, t, cause, causes = { ... }, x, y, cmd = { vx, vy, va },
--                    -- speed = { vx, vy, va } (measured, robot frame), tilt_dir ('front', 'back', 'left', 'right') }
--   c:table(minutes) -- lines: falls per cause, per robot, per robot-minute
--   c:write_csv(path)
--   census.classify(params, history, k, field)  -- the cause of the fall whose tip is history[k]
--   census.fell(down, rec, tip_angle)  -- the one definition of a fall that every count here uses (the
--                    -- census, the referee's team falls in Tools/match/rules.lua, the per-robot tally in
--                    -- Tools/match/tally.lua, the soak's falls=): rec = { fallen, roll, pitch }, down the
--                    -- state it returned at the last look (nil at first); returns (a new fall?, down)
--
-- The tip: the first look of the last run of looks whose torso tilt exceeds params.tip_angle before the
-- truth's fallen (the sim's fall_angle). The causes, the first that applies in this order:
--   push        a push acted within params.window s before the tip
--   standup     the motion state was a stand-up within params.standup_after s before the tip, or
--               the truth said fallen then (a stand-up that failed)
--   kick        a kick (kick_left/kick_right or a kick out of the walk) within params.window s
--   goal        the torso within params.goal m of a goal's frame (posts, side and back nets) within
--               params.window s (walked into the goal)
--   contact     another robot's torso within params.contact m within params.window s
--   ball        the ball's centre within params.ball m of the torso's ground point within params.window s
--   turn        |commanded or measured turn rate| > params.turn_rate, or |commanded or measured sideways
--               speed| > params.side_speed, within params.window s (a turn or a sideways step)
--   walking     the walk state with a command or a measured speed (walking straight)
--   standing    else
-- Every cause that applies is kept in `causes` (the table counts the first).
local M = {}
M.__index = M

M.CAUSES = { 'push', 'standup', 'kick', 'goal', 'contact', 'ball', 'turn', 'walking', 'standing' }
M.NAMES = { push = 'after a push', standup = 'failed stand-up', kick = 'kick', goal = 'goal frame / net',
  contact = 'robot contact',
  ball = 'ball at the feet', turn = 'turn / sideways step', walking = 'walking straight', standing = 'standing' }

local KEYS = { 'tip_angle', 'window', 'standup_after', 'goal', 'contact', 'ball', 'turn_rate', 'side_speed',
  'moving', 'history' }

local function check(params)
  if type(params) ~= 'table' then error('census: referee.census (Config/common/game.lua) is missing', 3) end
  for _, k in ipairs(KEYS) do
    local v = params[k]
    if type(v) ~= 'number' or v ~= v or v < 0 then
      error(string.format('census: referee.census.%s (Config/common/game.lua) must be a number >= 0, got %s',
        k, tostring(v)), 3)
    end
  end
end

local function tilt(r) return math.sqrt(r.roll * r.roll + r.pitch * r.pitch) end

-- One fall: the truth says fallen and the robot has got up since its last fall (the truth not fallen and
-- its torso tilt under tip_angle). The sim's fallen flag alone switches on again each time a lying robot
-- rolls past its fall angle, and the motion process's own count (motion.falls) each time it detects a fall
-- during a stand-up: both count one fall two or more times.
function M.fell(down, rec, tip_angle)
  if type(rec.roll) ~= 'number' or type(rec.pitch) ~= 'number' then
    error('census.fell: a look needs the truth\'s roll and pitch (numbers)', 2)
  end
  if not rec.fallen and tilt(rec) < tip_angle then down = false end
  if rec.fallen and not down then return true, true end
  return false, down
end

local function wrap(a) return (a + math.pi) % (2 * math.pi) - math.pi end

-- Measured velocity in the robot frame at record k of history h: over the looks from about 0.3 s before.
local function measured(h, k)
  local b = h[k]
  local a = b
  for j = k - 1, 1, -1 do
    a = h[j]
    if b.t - a.t >= 0.3 then break end
  end
  local dt = b.t - a.t
  if dt <= 0 then return { 0, 0, 0 } end
  local dx, dy = (b.x - a.x) / dt, (b.y - a.y) / dt
  local c, s = math.cos(b.yaw), math.sin(b.yaw)
  return { c * dx + s * dy, -s * dx + c * dy, wrap(b.yaw - a.yaw) / dt }
end
M.measured = measured

-- The index of the tip in history h, whose last record is the first fallen one.
function M.tip_index(params, h)
  local k = #h
  while k > 1 and tilt(h[k - 1]) > params.tip_angle do k = k - 1 end
  -- the last look still below the tip angle: the state the robot was in when it tipped
  return math.max(1, k - 1)
end

-- Distance from (x, y) to the segment (ax, ay)-(bx, by).
local function to_segment(x, y, ax, ay, bx, by)
  local dx, dy = bx - ax, by - ay
  local u = math.max(0, math.min(1, ((x - ax) * dx + (y - ay) * dy) / (dx * dx + dy * dy)))
  return math.sqrt((ax + u * dx - x) ^ 2 + (ay + u * dy - y) ^ 2)
end

-- Distance from (x, y) to the nearest goal's frame: the side nets from the posts back, the back net.
function M.goal_distance(field, x, y)
  local best = math.huge
  local l, g, d = field.length / 2, field.goal_width / 2, field.goal_depth
  for _, sx in ipairs({ -1, 1 }) do
    for _, sy in ipairs({ -1, 1 }) do best = math.min(best, to_segment(x, y, sx * l, sy * g, sx * (l + d), sy * g)) end
    best = math.min(best, to_segment(x, y, sx * (l + d), -g, sx * (l + d), g))
  end
  return best
end

local STANDUP = { standup_front = true, standup_back = true }
local KICK = { kick_left = true, kick_right = true }

-- The causes of the fall whose history is h (oldest first) and tip record index k.
function M.classify(params, h, k, field)
  local tip = h[k]
  local causes, has = {}, {}
  local function add(c) if not has[c] then has[c] = true causes[#causes + 1] = c end end
  local speed = measured(h, k)
  for j = k, 1, -1 do
    local r = h[j]
    local age = tip.t - r.t
    if age > math.max(params.window, params.standup_after) then break end
    if age <= params.standup_after and (STANDUP[r.state] or r.fallen) then add('standup') end
    if age <= params.window then
      if r.pushed then add('push') end
      if KICK[r.state] or r.kick then add('kick') end
      if field and M.goal_distance(field, r.x, r.y) <= params.goal then add('goal') end
      for _, o in ipairs(r.others or {}) do
        if math.sqrt((o[1] - r.x) ^ 2 + (o[2] - r.y) ^ 2) <= params.contact then add('contact') end
      end
      if r.ball and math.sqrt((r.ball[1] - r.x) ^ 2 + (r.ball[2] - r.y) ^ 2) <= params.ball then add('ball') end
      local cmd = r.cmd or { 0, 0, 0 }
      local m = measured(h, j)
      if math.abs(cmd[3]) > params.turn_rate or math.abs(m[3]) > params.turn_rate
        or math.abs(cmd[2]) > params.side_speed or math.abs(m[2]) > params.side_speed then
        add('turn')
      end
    end
  end
  local cmd = tip.cmd or { 0, 0, 0 }
  local moving = math.abs(cmd[1]) > params.moving or math.abs(cmd[2]) > params.moving
    or math.sqrt(speed[1] ^ 2 + speed[2] ^ 2) > params.moving
  if tip.state == 'walk' and moving then add('walking') end
  add('standing')
  local first
  for _, c in ipairs(M.CAUSES) do
    if has[c] then first = c break end
  end
  return first, causes, speed
end

function M.new(params, names, field)
  check(params)
  return setmetatable({ p = params, names = names or {}, field = field, hist = {}, down = {}, pushes = {},
    falls = {} }, M)
end

function M:push(i, t)
  self.pushes[i] = t
end

function M:look(i, rec)
  local h = self.hist[i] or {}
  self.hist[i] = h
  if self.pushes[i] and rec.t - self.pushes[i] <= self.p.window then rec.pushed = true end
  h[#h + 1] = rec
  while #h > 1 and rec.t - h[1].t > self.p.history do table.remove(h, 1) end
  local fell
  fell, self.down[i] = M.fell(self.down[i], rec, self.p.tip_angle)
  if not fell then return nil end
  local k = M.tip_index(self.p, h)
  local cause, causes, speed = M.classify(self.p, h, k, self.field)
  local tip = h[k]
  local dir
  if math.abs(rec.pitch) >= math.abs(rec.roll) then dir = rec.pitch > 0 and 'front' or 'back'
  else dir = rec.roll > 0 and 'right' or 'left' end
  local f = { robot = i, name = self.names[i] or tostring(i), t = tip.t, cause = cause, causes = causes,
    x = tip.x, y = tip.y, yaw = tip.yaw, cmd = tip.cmd or { 0, 0, 0 }, speed = speed, tilt_dir = dir,
    state = tip.state or '?' }
  self.falls[#self.falls + 1] = f
  return f
end

-- One line about a fall (the match's and the soak's event log).
function M.line(f)
  return string.format('fall %s: %s (%s) at %.2f %.2f, command %.2f %.2f %.2f, measured %.2f %.2f %.2f, %s, '
    .. 'motion %s', f.name, M.NAMES[f.cause], table.concat(f.causes, ','), f.x, f.y, f.cmd[1], f.cmd[2], f.cmd[3],
    f.speed[1], f.speed[2], f.speed[3], f.tilt_dir, f.state)
end

-- The census table: falls per cause (count, share, mean commanded and measured forward speed) and the rate
-- per robot-minute over `robot_minutes`.
function M:table(robot_minutes)
  local out = { string.format('fall census: %d falls in %.1f robot-minutes = %.2f per robot-minute', #self.falls,
    robot_minutes, robot_minutes > 0 and #self.falls / robot_minutes or 0) }
  out[#out + 1] = string.format('  %-22s %5s %6s %8s %8s %8s', 'cause', 'falls', 'share', 'cmd vx', 'meas vx',
    'per min')
  for _, c in ipairs(M.CAUSES) do
    local n, cv, mv = 0, 0, 0
    for _, f in ipairs(self.falls) do
      if f.cause == c then n = n + 1 cv = cv + f.cmd[1] mv = mv + f.speed[1] end
    end
    if n > 0 then
      out[#out + 1] = string.format('  %-22s %5d %5.0f%% %8.2f %8.2f %8.3f', M.NAMES[c], n, 100 * n / #self.falls,
        cv / n, mv / n, robot_minutes > 0 and n / robot_minutes or 0)
    end
  end
  return out
end

function M:write_csv(path)
  local f = assert(io.open(path, 'w'))
  f:write('robot,name,t,cause,causes,x,y,yaw,cmd_vx,cmd_vy,cmd_va,vx,vy,va,tilt,state\n')
  for _, r in ipairs(self.falls) do
    f:write(string.format('%d,%s,%.2f,%s,%s,%.3f,%.3f,%.3f,%.3f,%.3f,%.3f,%.3f,%.3f,%.3f,%s,%s\n', r.robot, r.name,
      r.t, r.cause, table.concat(r.causes, ' '), r.x, r.y, r.yaw, r.cmd[1], r.cmd[2], r.cmd[3], r.speed[1],
      r.speed[2], r.speed[3], r.tilt_dir, r.state))
  end
  f:close()
end

return M
