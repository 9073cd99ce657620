-- What a key pose must be (Lib/Config.lua checks it on every load of a concern keyposes/<name>;
-- the keys and their meaning: Lib/teleop.lua, docs/teleoperation.md "Key poses"). The limbs' names
-- and the joints against the body and the teleop config are checked in Lib/teleop.lua.
local function finite(x) return type(x) == 'number' and x == x and x ~= math.huge and x ~= -math.huge end

local MODES = { free = true, hold = true, follow = true }
local LIMB_KEYS = { mode = true, pos = true }

local function vec(v, n)
  if type(v) ~= 'table' or #v ~= n then return false end
  for i = 1, n do if not finite(v[i]) then return false end end
  return true
end

local function limbs(v)
  if type(v) ~= 'table' or next(v) == nil then return 'must map limbs (lhand, rhand, pelvis, lfoot, rfoot) to modes' end
  for name, l in pairs(v) do
    if type(name) ~= 'string' then return 'must be named by strings', tostring(name) end
    if type(l) ~= 'table' then return "must be a table { mode = 'free' | 'hold' | 'follow', pos }", name end
    for k in pairs(l) do
      if not LIMB_KEYS[k] then return 'is not a key of a limb (mode, pos)', name .. '.' .. tostring(k) end
    end
    if not MODES[l.mode] then return "must be 'free', 'hold' or 'follow'", name .. '.mode' end
    if l.mode == 'free' and not vec(l.pos, 3) then
      return 'must be 3 finite numbers { x, y, z } (m, stance frame): a free limb has a target', name .. '.pos'
    end
    if l.mode ~= 'free' and l.pos ~= nil then return 'is for a free limb only', name .. '.pos' end
  end
  return true
end

return {
  doc = 'string',
  -- s: the segment from the pose before to this one
  duration = function(v)
    if not finite(v) or v < 0.2 or v > 60 then return 'must be a number of seconds in 0.2..60' end
    return true
  end,
  limbs = limbs,
  -- optional: the centre of mass over { x, y } (m, stance frame) instead of the stance's middle
  com = function(v)
    if v == nil or vec(v, 2) then return true end
    return 'must be 2 finite numbers { x, y } (m, stance frame)'
  end,
  -- optional: joints set directly (rad): the ones no limb target decides (a wrist's yaw, the neck)
  joints = function(v)
    if v == nil then return true end
    if type(v) ~= 'table' then return 'must map joint names to angles (rad)' end
    for j, a in pairs(v) do
      if type(j) ~= 'string' or not finite(a) then return 'must be a finite angle (rad)', tostring(j) end
    end
    return true
  end,
}
