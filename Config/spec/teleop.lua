-- What the teleoperation config's values must be (Lib/Config.lua checks it on every load; the keys
-- and their meaning: Config/common/teleop.lua).
local function finite(x) return type(x) == 'number' and x == x and x ~= math.huge and x ~= -math.huge end
local function at_least(lo, what)
  return function(v)
    if not finite(v) or v < lo then return string.format('must be a number >= %g (%s)', lo, what) end
    return true
  end
end

local function task(v)
  if type(v) ~= 'table' then return 'must be a table { level, gain, max_rate }' end
  if type(v.level) ~= 'number' or v.level < 1 or v.level % 1 ~= 0 then return 'must be an integer >= 1', 'level' end
  if not finite(v.gain) or v.gain <= 0 then return 'must be a number > 0 (1/s)', 'gain' end
  if not finite(v.max_rate) or v.max_rate <= 0 then return 'must be a number > 0 (m/s)', 'max_rate' end
  return true
end

local function limbs(v)
  if type(v) ~= 'table' or next(v) == nil then return 'must map limb names to { frame, link }' end
  for name, l in pairs(v) do
    if type(l) ~= 'table' or type(l.frame) ~= 'string' then return 'must be { frame = a frame of the body }', name end
    if l.link ~= nil and type(l.link) ~= 'string' then return 'must name a link of the body', name .. '.link' end
  end
  return true
end

return {
  limbs = limbs,
  solve = {
    share = function(v)
      if not finite(v) or v <= 0 or v > 1 then return 'must be a number in (0, 1]' end
      return true
    end,
    hand = task, pelvis = task, hold = task, com = task,
  },
  check = {
    reach = at_least(1e-4, 'm'), limit_margin = at_least(0, 'rad'), collision_margin = at_least(0, 'm'),
    com_margin = at_least(0, 'm'), collision_skip_joints = at_least(1, 'joints'), foot_drift = at_least(1e-4, 'm'),
    speed_share = function(v)
      if not finite(v) or v <= 0 or v > 1 then return 'must be a number in (0, 1]' end
      return true
    end,
  },
  executor = {
    link_timeout = at_least(0.01, 's'), start_tolerance = at_least(0, 'rad'), hardness = at_least(0, '0..1'),
    on_lost = function(v)
      if v ~= 'finish' and v ~= 'hold' then return "must be 'finish' or 'hold'" end
      return true
    end,
  },
}
