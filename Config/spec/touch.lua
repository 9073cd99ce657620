-- What the touch motion's values must be (Lib/Config.lua checks it on every load of the touch
-- concern; the keys and their meaning: Config/common/touch.lua). The joint names are checked against
-- the body where it is known (Player/Motion/states/touch.lua).
local function finite(x) return type(x) == 'number' and x == x and x ~= math.huge and x ~= -math.huge end

local SENSORS = { lhand = true, rhand = true }

local function arms(v)
  if type(v) ~= 'table' then return 'must be a list of { sensor, to }' end
  for i, a in ipairs(v) do
    if type(a) ~= 'table' then return 'must be a table { sensor, to }', i end
    if not SENSORS[a.sensor] then return "must be 'lhand' or 'rhand'", i .. '.sensor' end
    if type(a.to) ~= 'table' or next(a.to) == nil then return 'must name joints and their angles', i .. '.to' end
    for name, q in pairs(a.to) do
      if type(name) ~= 'string' then return 'must be joint = angle', i .. '.to' end
      if not finite(q) then return 'must be a finite angle (rad)', i .. '.to.' .. name end
    end
  end
  return true
end

local function positive(v)
  if finite(v) and v > 0 then return true end
  return 'must be a number > 0'
end

local function nonneg(v)
  if finite(v) and v >= 0 then return true end
  return 'must be a number >= 0'
end

return { arms = arms, speed = positive, force = positive, press = positive, confirm = nonneg }
