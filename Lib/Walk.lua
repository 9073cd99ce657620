-- The walk from Lua and the REPL: velocity commands and run-time parameter changes.
--
--   Walk.set_velocity(0.2, 0, 0.3)   -- m/s forward, m/s left, rad/s; clamped to the limits of
--                                     -- the body's walk.lua (Config/robots/<ROBOT>/); NaN/inf refused (nil, message)
--   Walk.get_velocity()              -- the command; Walk.velocity() the current rate-limited speed
--   Walk.set('tStep', 0.3)           -- change a walk parameter while walking (checked here and
--   Walk.set('feedback.ankle', {0.1, 0.2})  -- again in the motion process; applied at its next tick)
--   Walk.reload()                    -- re-read the body's walk.lua (Config/robots/<ROBOT>/) in the motion process
--   Walk.param_status()              -- 'applied' / 'pending' / the reason of a refusal
--   Walk.get('tStep')                -- value in the config file (as this process read it)
--   Walk.kick('forward', 'left', 0.2, 0.05)  -- a kick out of the walk ('forward' or 'side') with that
--                                     -- foot on its next step, through the ball at (x, y) m in the
--                                     -- robot frame (optional: else the config's nominal spot);
--                                     -- Walk.kick_status(): phase ('none', 'asked', 'kicking'), kicks done
-- Talks to the motion process through the `motion` shm block (velocity, param_*).
local shm = require('shm')
local Config = require('Config')
local walkgen = require('Motion.walk')

local M = {}

local motion = shm.lazy('motion')

local params
local function config()
  params = params or Config.load('walk')
  return params
end

-- Sets the walk velocity command; returns the clamped command, or nil and a message when refused.
function M.set_velocity(vx, vy, va)
  local cx, cy, ca = walkgen.clamp_velocity(config(), vx, vy or 0, va or 0)
  if not cx then
    return nil, 'Walk.set_velocity: refused: ' .. cy
  end
  motion():write(function(m)
    m.velocity[0], m.velocity[1], m.velocity[2] = cx, cy, ca
  end)
  return cx, cy, ca
end

function M.get_velocity() local m = motion() return m.velocity[0], m.velocity[1], m.velocity[2] end
function M.velocity()
  local m = motion()
  return m.walk_velocity[0], m.walk_velocity[1], m.walk_velocity[2]
end
function M.stop() return M.set_velocity(0, 0, 0) end

local function finite(x) return type(x) == 'number' and x == x and x ~= math.huge and x ~= -math.huge end

local KINDS = { forward = 1, side = 2 }
local PHASES = { [0] = 'none', [1] = 'asked', [2] = 'kicking' }

-- Asks the walk for a kick out of the walk (see the header); errors on a caller mistake.
-- Walk.kick(nil) cancels a request not yet honoured.
function M.kick(kind, foot, bx, by)
  local k = 0
  if kind ~= nil then
    k = KINDS[kind] or error("Walk.kick: kind must be 'forward' or 'side', got '" .. tostring(kind) .. "'", 2)
    if foot ~= 'left' and foot ~= 'right' then
      error("Walk.kick: foot must be 'left' or 'right', got '" .. tostring(foot) .. "'", 2)
    end
    if bx ~= nil and not (finite(bx) and finite(by)) then error('Walk.kick: the ball needs finite x and y', 2) end
  end
  motion():write(function(m)
    m.kick_request[0], m.kick_request[1] = k, foot == 'right' and 1 or 0
    m.kick_ball[0], m.kick_ball[1], m.kick_ball[2] = bx or 0, by or 0, bx and 1 or 0
    m.kick_seq[0] = m.kick_seq[0] + 1
  end)
  return true
end

-- The walk kick's phase ('none', 'asked', 'kicking') and the number of kicks done.
function M.kick_status()
  local m = motion()
  return PHASES[m.kick_phase[0]] or tostring(m.kick_phase[0]), m.kicks[0]
end

-- Resolves a key path 'a.b' in a table: returns parent table, last key, current value.
local function lookup(t, path)
  local parent, key = t, nil
  for part in path:gmatch('[^%.]+') do
    if key ~= nil then
      local v = rawget(parent, key)
      if type(v) ~= 'table' then return nil end
      parent = v
    end
    key = tonumber(part) or part
  end
  if key == nil then return nil end
  return parent, key, rawget(parent, key)
end
M.lookup = lookup

-- Checks a change of walk parameter `name` to `value` against params; returns the list of values
-- or nil, status code, message.
function M.check(p, name, value)
  local _, _, cur = lookup(p, name)
  if cur == nil then return nil, -1, "unknown walk parameter '" .. tostring(name) .. "'" end
  if type(cur) == 'number' then
    if not finite(value) then return nil, -2, "walk parameter '" .. name .. "' must be a finite number" end
    return { value }
  end
  if type(cur) ~= 'table' or type(value) ~= 'table' or #value ~= #cur or #cur == 0 or #cur > 4 then
    return nil, -2, string.format("walk parameter '%s' must be a list of %d numbers", name,
      type(cur) == 'table' and #cur or 1)
  end
  for i = 1, #cur do
    if type(cur[i]) ~= 'number' or not finite(value[i]) then
      return nil, -2, string.format("walk parameter '%s': element %d must be a finite number", name, i)
    end
  end
  return value
end

local function send(name, values)
  motion():write(function(m)
    local n = #name
    for i = 0, 63 do m.param_name[i] = i < n and name:byte(i + 1) or 0 end
    m.param_count[0] = values and #values or 0
    for i = 1, values and #values or 0 do m.param_value[i - 1] = values[i] end
    m.param_seq[0] = m.param_seq[0] + 1
  end)
end

-- Changes a walk parameter in the running motion process (checked; errors on a caller mistake).
-- One change at a time: while the previous one is not yet taken up by the motion process (it
-- takes one tick), returns nil, 'pending' -- try again after wait(0.01).
function M.set(name, value)
  if type(name) ~= 'string' or #name == 0 or #name > 63 then error('Walk.set: parameter name expected', 2) end
  local values, _, msg = M.check(config(), name, value)
  if not values then error('Walk.set: ' .. msg, 2) end
  local m = motion()
  if m.param_ack[0] ~= m.param_seq[0] and m.pid[0] ~= 0 then return nil, 'pending' end
  send(name, values)
  -- this process's copy too (set_velocity clamps with it)
  local parent, key, cur = lookup(config(), name)
  if type(cur) == 'number' then rawset(parent, key, values[1])
  else for i = 1, #values do cur[i] = values[i] end end
  return true
end

-- Re-reads the walk config file in the motion process (nil, 'pending' as for set).
function M.reload()
  local m = motion()
  if m.param_ack[0] ~= m.param_seq[0] and m.pid[0] ~= 0 then return nil, 'pending' end
  send('', nil)
  return true
end

-- Result of the last set/reload: 'applied', 'pending', or the reason it was refused.
local STATUS = { [0] = 'applied', [-1] = 'unknown parameter', [-2] = 'bad value', [-3] = 'config reload failed' }
function M.param_status()
  local m = motion()
  if m.param_ack[0] ~= m.param_seq[0] then return 'pending' end
  return STATUS[m.param_status[0]] or tostring(m.param_status[0])
end

-- A walk parameter as this process read it from the config file.
function M.get(name)
  local _, _, v = lookup(config(), name)
  return v
end

return M
