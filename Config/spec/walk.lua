-- What the walk's values must be, beyond the types the layers keep (Lib/Config.lua checks this on
-- every load of the walk config; the keys and their meaning: Config/common/walk.lua). A value the
-- walk cannot use fails here, naming the file and the key, instead of showing as NaN steps or a
-- joint driven from nothing. The arms' joint names against the body's joints are checked where the
-- body is known (Player/Motion/walk.lua, Walk:bind).
local function finite(x) return type(x) == 'number' and x == x and x ~= math.huge and x ~= -math.huge end
local function shown(v) return type(v) == 'string' and "'" .. v .. "'" or tostring(v) end

-- a number from lo, inclusive unless open ('>'), to hi (nil: no bound)
local function number(lo, open, hi)
  local what = 'a number'
  if lo then what = what .. (open and ' > ' or ' >= ') .. lo end
  if hi then what = 'a number in ' .. lo .. '..' .. hi end
  return function(v)
    if finite(v) and (not lo or v > lo or (not open and v == lo)) and (not hi or v <= hi) then return true end
    return 'must be ' .. what .. ', got ' .. shown(v)
  end
end

-- one of the strings given
local function one_of(...)
  local names = { ... }
  return function(v)
    for _, n in ipairs(names) do if v == n then return true end end
    return "must be '" .. table.concat(names, "' or '") .. "', got " .. shown(v)
  end
end

-- { x, y }: two numbers >= 0
local function pair_nonneg(v)
  if type(v) == 'table' and finite(v[1]) and finite(v[2]) and v[1] >= 0 and v[2] >= 0 and v[3] == nil then
    return true
  end
  return 'must be { x, y }, numbers >= 0'
end

local function turn_step(v)
  if v == false then return true end
  local va = type(v) == 'table' and v.va
  if type(v) == 'table' and finite(v.tStep) and v.tStep > 0 and type(va) == 'table' and finite(va[1])
      and finite(va[2]) and va[1] >= 0 and va[2] > va[1] then
    return true
  end
  return 'must be false or { tStep = s > 0, va = { lo, hi } } rad/s with 0 <= lo < hi'
end

-- arms = { l = { posture = { joint = rad, ... }, pitch = joint, roll = joint }, r = ... }; an arm
-- without a pitch or roll joint has false there (filled in here)
local function arms(v)
  if type(v) ~= 'table' then return 'must be a table { l = ..., r = ... }' end
  for side, a in pairs(v) do
    if side ~= 'l' and side ~= 'r' then return "must have the sides 'l' and 'r' only", tostring(side) end
    if type(a) ~= 'table' or type(a.posture) ~= 'table' then
      return 'must be a table of joint = rad', side .. '.posture'
    end
    for name, rad in pairs(a.posture) do
      if type(name) ~= 'string' then return 'must name its joints', side .. '.posture' end
      if not finite(rad) then return 'must be a finite number', side .. '.posture.' .. name end
    end
    for which, name in pairs(a) do
      if which ~= 'posture' then
        if which ~= 'pitch' and which ~= 'roll' then
          return 'is not a key of an arm (posture, pitch, roll)', side .. '.' .. tostring(which)
        end
        if name ~= false and (type(name) ~= 'string' or a.posture[name] == nil) then
          return string.format("must name a joint of 'arms.%s.posture' or be false, got %s", side, shown(name)),
            side .. '.' .. which
        end
      end
    end
    if a.pitch == nil then a.pitch = false end
    if a.roll == nil then a.roll = false end
  end
  return true
end

-- A list of phases, each { duration = s > 0, field = number, ... } with the fields named in
-- `fields` only; a field a phase leaves out is 0 (filled in here, so the kicks read every field).
local function phases(fields)
  local known = {}
  for _, f in ipairs(fields) do known[f] = true end
  return function(v)
    if type(v) ~= 'table' or #v == 0 then return 'must be a list of phases { duration = s, ... }' end
    for i, ph in ipairs(v) do
      if type(ph) ~= 'table' then return 'must be a table', i end
      if not (finite(ph.duration) and ph.duration > 0) then
        return 'must be a number > 0, got ' .. shown(ph.duration), i .. '.duration'
      end
      for k, x in pairs(ph) do
        if k ~= 'duration' then
          if not known[k] then
            return 'is not a field of a phase (duration, ' .. table.concat(fields, ', ') .. ')', i .. '.' .. tostring(k)
          end
          if not finite(x) then return 'must be a finite number, got ' .. shown(x), i .. '.' .. k end
        end
      end
      for _, f in ipairs(fields) do
        if ph[f] == nil then ph[f] = 0 end
      end
    end
    return true
  end
end

local kick_body = phases({ 'shift', 'lean', 'height', 'tilt', 'arms' })
local kick_leg = phases({ 'x', 'y', 'z', 'hip', 'knee', 'ankle', 'arm' })
local walk_kick_phases = phases({ 'x', 'y', 'z', 'hip', 'knee', 'ankle', 'hipRoll', 'tilt', 'arms', 'arm' })

-- walkKick: false, or its kinds (forward, side), each with its phases; ballMax (m) may be left out
-- (false: no ball is too far ahead)
local function walk_kick(v)
  if v == false then return true end
  if type(v) ~= 'table' then return 'must be false or a table (expire, maxSpeed, forward, side)' end
  for _, kind in ipairs({ 'forward', 'side' }) do
    local k = v[kind]
    if k ~= nil then
      if type(k) ~= 'table' then return 'must be a table', kind end
      if k.ballMax == nil then k.ballMax = false end
      if k.ballMax ~= false and not finite(k.ballMax) then
        return 'must be false or a number (m), got ' .. shown(k.ballMax), kind .. '.ballMax'
      end
      local ok, sub = walk_kick_phases(k.phases)
      if ok ~= true then return ok, kind .. '.phases' .. (sub and '.' .. sub or '') end
    end
  end
  return true
end

local nonneg = number(0)
return {
  engine = one_of('analytic', 'preview'),
  turnToeIn = number(0, false, 1),
  hipYawLead = nonneg,
  turnStep = turn_step,
  arms = arms,
  balance = {
    zmpGain = pair_nonneg, walkGain = pair_nonneg,
    leakTime = number(0, true),
    maxShift = nonneg, maxRate = nonneg, filterTime = nonneg, walkFilterTime = nonneg, minForce = nonneg,
    sensorHeight = nonneg,
  },
  kick = { body = kick_body, leg = kick_leg },
  walkKick = walk_kick,
}
