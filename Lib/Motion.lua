-- The motion process from Lua and the REPL: request a motion, read its state.
--
--   Motion.request('walk')     -- relax, sit, stand, walk, kick_left, kick_right, wbc (Lib/WBC.lua),
--                              -- pattern, touch (the arms until the hands feel a touch: touch.lua)
--   Motion.request('wbc', { skill = 'hello_bye' })   -- whole-body control running a skill (WBC.skill)
--   Motion.request('teleop')   -- the executor of checked teleoperation trajectories (Lib/Teleop.lua)
--   Motion.request('pattern', { file = 'build/pattern/hoap3_walk.csv' })
--                              -- plays a joint trajectory file (Lib/trajectory.lua, made ahead by
--                              -- Tools/pattern/gen_pattern.lua) from the current pose, then stance;
--                              -- a file that does not fit the body is refused here, naming its line
--   Motion.pattern_time()      -- s into the file being played (nil: none)
--   Motion.state()             -- 'stance', 'walk', 'falling', 'standup_front', ...
--   Motion.falls()             -- falls detected since the motion process started
--   Motion.owners()            -- per joint group: 'motion' (its state drives it), 'caller' (taken with
--                              -- Body.set_*_command, see Lib/Body.lua), 'held' (nobody: it holds), 'mixed'
--   Motion.owner('head_pan')   -- the same for one joint
--
-- Talks to the motion process (Player/Motion/main.lua) through the `motion` shm block: a request
-- is the index of a state in Motion.STATES plus a bumped request_seq; the process picks it up at
-- its next tick. Requests are wishes: the process moves there through the states it must pass
-- (a walk stops before a kick; a stand-up ends in stance and goes back to walking if asked to).
local ffi = require('ffi')
local shm = require('shm')

local M = {}

-- the motion state machine's states, in the order of motion.state / motion.request
M.STATES = { 'relax', 'sit', 'stance', 'walk', 'kick_left', 'kick_right', 'falling', 'standup_front',
  'standup_back', 'wbc', 'pattern', 'touch', 'teleop' }
-- request names and the state each asks for
M.REQUESTS = { relax = 'relax', sit = 'sit', stand = 'stance', walk = 'walk', kick_left = 'kick_left',
  kick_right = 'kick_right', wbc = 'wbc', pattern = 'pattern', touch = 'touch', teleop = 'teleop' }

local index = {}
for i, s in ipairs(M.STATES) do index[s] = i - 1 end
M.INDEX = index

local motion = shm.lazy('motion')

local robot
local function body()
  robot = robot or require('Config').load('robot', { joints = 'table', groups = 'table' })
  return robot
end

-- 'pattern': { file = path } of a trajectory file that fits the body (read here: a bad file is an
-- error naming it and its line); the path made absolute (the motion process has its own cwd)
local function pattern_arg(args)
  local file = type(args) == 'table' and args.file
  if type(file) ~= 'string' or file == '' then
    error("Motion.request('pattern', { file = PATH }): the trajectory file's path is missing", 3)
  end
  if file:sub(1, 1) ~= '/' then file = (os.getenv('PWD') or '.') .. '/' .. file end
  if #file > 255 then error("Motion.request('pattern'): the path is longer than 255 bytes: " .. file, 3) end
  local ok, err = pcall(require('trajectory').load, file, body())
  if not ok then error("Motion.request('pattern'): " .. tostring(err), 3) end
  return file
end
-- 'wbc': optionally { skill = name }, checked first (a skill refused asks for nothing)
local function wbc_arg(args)
  if args == nil then return '' end
  if type(args) ~= 'table' then error("Motion.request('wbc', { skill = NAME }): the options must be a table", 3) end
  local ok, err = pcall(require('WBC').skill, args.skill)
  if not ok then error(err, 3) end
  return ''
end

-- 'touch': only for a body whose touch.lua lists arms
local function touch_arg()
  if #require('Config').load('touch').arms == 0 then
    error(string.format("Motion.request: the body '%s' has no arms to touch with (its touch.lua lists none)",
      require('Config').robot()), 3)
  end
  return ''
end

-- the requests that take an argument or a check: it returns the string the motion process gets
local ARGS = { pattern = pattern_arg, wbc = wbc_arg, touch = touch_arg }

-- Asks the motion process for a motion; errors on an unknown name or a bad argument.
function M.request(name, args)
  local s = M.REQUESTS[name]
  if not s then
    error(string.format("Motion.request: unknown motion '%s' (%s)", tostring(name),
      'relax, sit, stand, walk, kick_left, kick_right, wbc, pattern, touch'), 2)
  end
  if args ~= nil and not ARGS[name] then error("Motion.request: '" .. name .. "' takes no options", 2) end
  local arg = ARGS[name] and ARGS[name](args) or ''
  local b = motion()
  b:write(function(m)
    ffi.fill(m.request_arg, 256)
    ffi.copy(m.request_arg, arg)
    m.request[0] = index[s]
    m.request_seq[0] = m.request_seq[0] + 1
  end)
  return true
end

-- Name of the motion process's current state.
function M.state()
  return M.STATES[motion().state[0] + 1] or 'unknown'
end

-- Name of the last requested state (nil if none).
function M.requested()
  local r = motion().request[0]
  if r < 0 then return nil end
  return M.STATES[r + 1]
end

local WHO = { [0] = 'held', [1] = 'motion', [2] = 'caller' }

-- Who drives a joint (name or 1-based index): 'motion', 'caller' or 'held'.
function M.owner(joint)
  local names, i = body().joints, joint
  if type(joint) == 'string' then
    for k, name in ipairs(names) do if name == joint then i = k end end
  end
  if type(i) ~= 'number' or not names[i] then error("Motion.owner: unknown joint '" .. tostring(joint) .. "'", 2) end
  return WHO[motion().owner[i - 1]] or 'unknown'
end

-- Who drives each joint group of the body: { head = 'motion', waist = 'held', ... }.
function M.owners()
  local r, names, res = body(), {}, {}
  for k, name in ipairs(r.joints) do names[name] = k end
  local owner = motion().owner
  for g, members in pairs(r.groups) do
    local who
    for _, name in ipairs(members) do
      local w = WHO[owner[names[name] - 1]] or 'unknown'
      if who == nil then who = w elseif who ~= w then who = 'mixed' end
    end
    res[g] = who or 'held'
  end
  return res
end

function M.falls() return motion().falls[0] end
function M.pattern_time()
  local t = motion().pattern_time[0]
  if t == -1 then return nil end
  return t
end
function M.walking() return motion().walking[0] == 1 end
-- Walk odometry {x, y, yaw} (ground frame of the walk).
function M.odometry() return motion():get('odometry') end

return M
