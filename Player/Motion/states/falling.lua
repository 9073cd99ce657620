-- falling: go soft, arms in front of (or behind) the body to protect it, wait until the robot
-- lies still, then stand up from the front or the back.
local M = {}

-- every joint goes soft
M.owns = { 'all' }

function M.entry(c)
  local p = c.p
  for i = 1, c.n do
    c.q[i] = c.pos[i]
    c.h[i] = p.fallHardness
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
  -- lying still, the accelerometer reads gravity in the torso frame: face down it points along
  -- -x (Euler angles are no help here: they flip near a pitch of 90 deg)
  if c.acc[1] < 0 then return 'front' end
  return 'back'
end

return M
