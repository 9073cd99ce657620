-- The motion process from Lua and the REPL: request a motion, read its state.
--
--   Motion.request('walk')     -- relax, sit, stand, walk, kick_left, kick_right
--   Motion.state()             -- 'stance', 'walk', 'falling', 'standup_front', ...
--   Motion.falls()             -- falls detected since the motion process started
--
-- Talks to the motion process (Player/Motion/main.lua) through the `motion` shm block: a request
-- is the index of a state in Motion.STATES plus a bumped request_seq; the process picks it up at
-- its next tick. Requests are wishes: the process moves there through the states it must pass
-- (a walk stops before a kick; a stand-up ends in stance and goes back to walking if asked to).
local shm = require('shm')

local M = {}

-- the motion state machine's states, in the order of motion.state / motion.request
M.STATES = { 'relax', 'sit', 'stance', 'walk', 'kick_left', 'kick_right', 'falling', 'standup_front',
  'standup_back' }
-- request names and the state each asks for
M.REQUESTS = { relax = 'relax', sit = 'sit', stand = 'stance', walk = 'walk', kick_left = 'kick_left',
  kick_right = 'kick_right' }

local index = {}
for i, s in ipairs(M.STATES) do index[s] = i - 1 end
M.INDEX = index

local motion = shm.lazy('motion')

-- Asks the motion process for a motion; errors on an unknown name.
function M.request(name)
  local s = M.REQUESTS[name]
  if not s then
    error(string.format("Motion.request: unknown motion '%s' (%s)", tostring(name),
      'relax, sit, stand, walk, kick_left, kick_right'), 2)
  end
  local b = motion()
  b:write(function(m)
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

function M.falls() return motion().falls[0] end
function M.walking() return motion().walking[0] == 1 end
-- Walk odometry {x, y, yaw} (ground frame of the walk).
function M.odometry() return motion():get('odometry') end

return M
