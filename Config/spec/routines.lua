-- What a routine's values must be (Lib/Config.lua checks it on every load of a concern
-- routines/<name>; the keys and their meaning: Lib/routine.lua).
local function finite(x) return type(x) == 'number' and x == x and x ~= math.huge and x ~= -math.huge end

local function step(s)
  if type(s) ~= 'table' then return 'must be a table { skill | walk | stand, seconds }' end
  local kinds = (s.skill ~= nil and 1 or 0) + (s.walk ~= nil and 1 or 0) + (s.stand ~= nil and 1 or 0)
  if kinds ~= 1 then return 'must have exactly one of skill (a name), walk ({ vx, vy, va }) or stand (true)' end
  if s.skill ~= nil and (type(s.skill) ~= 'string' or s.skill == '') then return 'must name a skill', 'skill' end
  if s.walk ~= nil then
    if type(s.walk) ~= 'table' or #s.walk ~= 3 then return 'must be { vx, vy, va } (m/s, m/s, rad/s)', 'walk' end
    for i = 1, 3 do if not finite(s.walk[i]) then return 'must be a finite number', 'walk.' .. i end end
  end
  if s.stand ~= nil and s.stand ~= true then return 'must be true', 'stand' end
  if not finite(s.seconds) or s.seconds <= 0 then return 'must be a number > 0 (s)', 'seconds' end
  for k in pairs(s) do
    if k ~= 'skill' and k ~= 'walk' and k ~= 'stand' and k ~= 'seconds' then
      return 'is not a key of a step (skill, walk, stand, seconds)', tostring(k)
    end
  end
  return true
end

local function steps(v)
  if type(v) ~= 'table' or #v == 0 then return 'must be a list of steps' end
  for i, s in ipairs(v) do
    local ok, sub = step(s)
    if ok ~= true then return ok, i .. (sub and '.' .. sub or '') end
  end
  return true
end

local function rounds(v)
  if type(v) == 'number' and v >= 1 and v % 1 == 0 then return true end
  return 'must be an integer >= 1'
end

return { steps = steps, rounds = rounds }
