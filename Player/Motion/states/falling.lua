-- falling: arms in front of (or behind) the body to protect it, wait until the robot lies still,
-- then stand up from the front or the back. Two policies, chosen by the walk config:
-- * without `fallPolicy` (the small bodies): every joint goes soft (fallHardness), then a stand-up;
-- * with `fallPolicy` (a robot too heavy to go limp or to get up by itself, the Hubo):
--   { pose = { joint = rad, ... } a protective pose by joint name (the arms' pitch still follows
--   fallArms, towards the fall), hardness = while falling (no collapse to limp), rest = 'hold'
--   (lying still: the pose stays held) or 'release' (lying still: torque off), standup = false
--   (no stand-up: it stays in falling until it is upright again, e.g. put back on its feet) }.
local M = {}

-- every joint
M.owns = { 'all' }

local function policy_of(p) return p.fallPolicy end

function M.entry(c)
  local p = c.p
  local policy = policy_of(p)
  local h = policy and policy.hardness or p.fallHardness
  for i = 1, c.n do
    c.q[i] = c.pos[i]
    c.h[i] = h
  end
  if policy then
    for name, rad in pairs(policy.pose) do
      local i = c.ji[name] or error(string.format("walk config: fallPolicy.pose names unknown joint '%s'",
        tostring(name)))
      c.q[i] = rad
    end
  end
  -- arms towards the side the robot falls to (pitch > 0: forwards; still small when detected), as
  -- a rotation about the torso's y axis through each arm's pitch joint (the walk config's arms)
  local a = c.angle[2] > 0 and p.fallArms[1] or p.fallArms[2]
  local w = c.walk
  for _, arm in pairs(w.arms) do
    if arm.pitch then c.q[arm.pitch] = a * w.ay[arm.pitch] end
  end
  c:scratch('falling').still_since = nil
end

function M.update(c)
  local p, d = c.p, c:scratch('falling')
  local g = c.gyro
  local moving = math.abs(g[1]) + math.abs(g[2]) + math.abs(g[3]) > p.fallStillRate
  if moving then d.still_since = nil elseif not d.still_since then d.still_since = c.t end
  if c:since() < p.fallSettleTime or not d.still_since or c.t - d.still_since < p.fallStillTime then return nil end
  local roll, pitch = c.angle[1], c.angle[2]
  -- did not fall after all
  if math.abs(pitch) < p.fallUprightAngle and math.abs(roll) < p.fallUprightAngle then return 'stand' end
  local policy = policy_of(p)
  if policy and policy.standup == false then
    -- lying: hold the pose, or let go of it
    if policy.rest == 'release' then
      for i = 1, c.n do c.h[i] = 0 end
    end
    return nil
  end
  -- lying still, the accelerometer reads gravity in the torso frame: face down it points along
  -- -x (Euler angles are no help here: they flip near a pitch of 90 deg)
  if c.acc[1] < 0 then return 'front' end
  return 'back'
end

return M
