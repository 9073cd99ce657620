-- falling: go soft, arms in front of (or behind) the body to protect it, wait until the robot
-- lies still, then stand up from the front or the back.
local M = {}

local still_since

function M.entry(c)
  local p = c.p
  for i = 1, c.n do
    c.q[i] = c.pos[i]
    c.h[i] = p.fallHardness
  end
  -- arms towards the side the robot falls to (pitch > 0: forwards; still small when detected)
  local fwd = c.angle[2] > 0
  local a = fwd and -1.2 or 0.8
  local ji, ay = c.ji, c.walk.ay
  c.q[ji.l_sho_pitch] = a * ay[ji.l_sho_pitch]
  c.q[ji.r_sho_pitch] = a * ay[ji.r_sho_pitch]
  still_since = nil
end

function M.update(c)
  local g = c.gyro
  local moving = math.abs(g[1]) + math.abs(g[2]) + math.abs(g[3]) > c.p.fallStillRate
  if moving then still_since = nil elseif not still_since then still_since = c.t end
  if c:since() < c.p.fallSettleTime or not still_since or c.t - still_since < 0.3 then return nil end
  local roll, pitch = c.angle[1], c.angle[2]
  if math.abs(pitch) < 0.5 and math.abs(roll) < 0.5 then return 'stand' end -- did not fall after all
  -- lying still, the accelerometer reads gravity in the torso frame: face down it points along
  -- -x (Euler angles are no help here: they flip near a pitch of 90 deg)
  if c.acc[1] < 0 then return 'front' end
  return 'back'
end

return M
