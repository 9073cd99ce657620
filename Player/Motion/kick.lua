-- Kick: the COM moves over the support foot, the kicking foot draws back, swings through and
-- returns, all as foot and COM targets through the walk's geometry and leg IK (so it follows the
-- walk's posture parameters on every robot). Phases come from the walk config's `kick.phases`:
--   { duration = s, shift = 0..1 (COM from the middle to over the support foot),
--     lean = m (optional: the body moves forward over the support foot, adding to the swing),
--     x = m, y = m (outward), z = m  (kicking foot offset from its stance position),
--     hip, knee, ankle = rad (optional: added to the kicking leg's pitch joints after the IK, as
--     rotations about the torso's y axis: negative hip swings the leg forward, positive knee bends) }
-- each reached from the previous phase with a smooth profile. A short phase (a few ms) makes the
-- servos run at their speed limit: that is the swing.
local Walk = require('Motion.walk')

local M = {}
local Kick = {}
Kick.__index = Kick

function M.new(walk)
  return setmetatable({ walk = walk, from = {}, cur = {}, done = true }, Kick)
end

local KEYS = { 'shift', 'lean', 'x', 'y', 'z', 'hip', 'knee', 'ankle', 'tilt', 'height', 'shp', 'skn', 'sank' }

-- Starts a kick with the foot on `side` ('left' or 'right') at time t.
function Kick:start(side, t)
  self.side = side
  self.t0 = t
  self.i = 1
  for _, k in ipairs(KEYS) do self.from[k], self.cur[k] = 0, 0 end
  self.done = false
  -- the walk must be at stance with the feet together
  self.walk:advance(0)
end

-- Writes the joint angles into q; returns true when the kick has ended.
function Kick:update(t, q, sensors, dt)
  local w = self.walk
  local p = w.p
  local phases = p.kick.phases
  local cur, from = self.cur, self.from
  while true do
    local ph = phases[self.i]
    local s = (t - self.t0) / ph.duration
    if s < 1 or self.i == #phases then
      if s > 1 then s = 1 end
      local a = s * s * (3 - 2 * s)
      for _, k in ipairs(KEYS) do cur[k] = from[k] + a * ((rawget(ph, k) or 0) - from[k]) end
      self.done = s >= 1 and self.i == #phases
      break
    end
    for _, k in ipairs(KEYS) do from[k] = rawget(ph, k) or 0 end
    self.t0 = self.t0 + ph.duration
    self.i = self.i + 1
  end
  local left = self.side == 'left'
  local uK = left and w.uLeft2 or w.uRight2    -- kicking foot at stance
  local uS = left and w.uRight2 or w.uLeft2    -- support foot
  local sgn = left and 1 or -1
  local mid = Walk.interp(0.5, w.uLeft2, w.uRight2)
  local sup = Walk.pose_global({ p.supportX, -sgn * p.kick.supportY, 0 }, uS)
  local cx = mid[1] + cur.shift * (sup[1] - mid[1]) + cur.lean * math.cos(mid[3])
  local cy = mid[2] + cur.shift * (sup[2] - mid[2]) + cur.lean * math.sin(mid[3])
  local foot = Walk.pose_global({ cur.x, sgn * cur.y, 0 }, uK)
  local ta = mid[3]
  local ox, oy = w.com_offset[1] + p.footX, w.com_offset[2]
  local c, sn = math.cos(ta), math.sin(ta)
  local tx, ty = cx - (c * ox - sn * oy), cy - (sn * ox + c * oy)
  local tz, tp = p.bodyHeight + cur.height, p.bodyTilt + cur.tilt
  local kp, sp = left and w.lpose or w.rpose, left and w.rpose or w.lpose
  Walk.foot_in_torso(kp, foot[1], foot[2], cur.z, foot[3], tx, ty, tz, ta, tp, 0)
  Walk.foot_in_torso(sp, uS[1], uS[2], 0, uS[3], tx, ty, tz, ta, tp, 0)
  local support = (cur.shift > 0.5) and (left and Walk.RIGHT or Walk.LEFT) or nil
  w:joint_angles(q, sensors, dt, support)
  w:update_com_offset(q, 0.3)
  local legi = w.legs[left and Walk.LEFT or Walk.RIGHT]
  local ay = w.ay
  q[legi[3]] = q[legi[3]] + ay[legi[3]] * cur.hip
  q[legi[4]] = q[legi[4]] + ay[legi[4]] * cur.knee
  q[legi[5]] = q[legi[5]] + ay[legi[5]] * cur.ankle
  local legs = w.legs[left and Walk.RIGHT or Walk.LEFT]
  q[legs[3]] = q[legs[3]] + ay[legs[3]] * cur.shp
  q[legs[4]] = q[legs[4]] + ay[legs[4]] * cur.skn
  q[legs[5]] = q[legs[5]] + ay[legs[5]] * cur.sank
  return self.done
end

return M
