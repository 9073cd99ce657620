-- Kick: the COM moves over the support foot, the kicking foot draws back, swings through and
-- returns, all as foot and COM targets through the walk's geometry and leg IK (so it follows the
-- walk's posture parameters on every robot). Two tracks from the walk config's `kick`, each a
-- list of phases reached one after the other, each over its `duration` with a smooth profile:
--   body = { { duration = s, shift = 0..1 (COM from the middle to over the support foot),
--              lean = m (the COM forward of that), height = m, tilt = rad (torso pitch, forward
--              positive), arms = rad (both arms back: against the pitch momentum of a torso
--              thrown back) }, ... }
--   leg  = { { duration = s, x = m, y = m (outward), z = m (kicking foot offset from its stance
--              position), hip, knee, ankle = rad (added to the kicking leg's pitch joints after
--              the IK, as rotations about the torso's y axis: negative hip swings the leg
--              forward, positive knee bends), arm = rad (the kicking side's arm back, the other
--              forward: against the leg's yaw moment) }, ... }
-- The tracks run side by side (the torso moves smoothly while the leg swings); the kick ends
-- when both have. A short leg phase (a few ms) makes the servos run at their speed limit: that
-- is the swing.
local Walk = require('Motion.walk')

local M = {}
local Kick = {}
Kick.__index = Kick

function M.new(walk)
  return setmetatable({ walk = walk, cur = {}, body = {}, leg = {}, qleg = {}, done = true, pitch = 0 }, Kick)
end

local BODY = { 'shift', 'lean', 'height', 'tilt', 'arms' }
local LEG = { 'x', 'y', 'z', 'hip', 'knee', 'ankle', 'arm' }

local function track_start(tr, keys, t, cur)
  tr.keys, tr.t0, tr.i, tr.from = keys, t, 1, tr.from or {}
  for _, k in ipairs(keys) do tr.from[k], cur[k] = 0, 0 end
end

-- Advances a track to time t: cur gets the profile between the previous phase's targets and the
-- current one's; returns true once the last phase is over.
local function track_update(tr, t, phases, cur)
  local from, keys = tr.from, tr.keys
  while true do
    local ph = phases[tr.i]
    local s = (t - tr.t0) / ph.duration
    if s < 1 or tr.i == #phases then
      if s > 1 then s = 1 end
      local a = s * s * (3 - 2 * s)
      for _, k in ipairs(keys) do cur[k] = from[k] + a * (ph[k] - from[k]) end
      return s >= 1 and tr.i == #phases
    end
    for _, k in ipairs(keys) do from[k] = ph[k] end
    tr.t0 = tr.t0 + ph.duration
    tr.i = tr.i + 1
  end
end

-- Starts a kick with the foot on `side` ('left' or 'right') at time t.
function Kick:start(side, t)
  self.side = side
  track_start(self.body, BODY, t, self.cur)
  track_start(self.leg, LEG, t, self.cur)
  self.done = false
  -- the walk must be at stance with the feet together
  self.walk:advance(0)
end

-- adds a pitch rotation (about the torso's y axis) to joint i
local function add_pitch(w, q, i, a) q[i] = q[i] + w.ay[i] * a end

-- Writes the joint angles into q; returns true when the kick has ended.
function Kick:update(t, q, sensors, dt)
  local w = self.walk
  local p = w.p
  local body_done = track_update(self.body, t, p.kick.body, self.cur)
  local leg_done = track_update(self.leg, t, p.kick.leg, self.cur)
  self.done = body_done and leg_done
  local cur = self.cur
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
  local kside, sside = left and Walk.LEFT or Walk.RIGHT, left and Walk.RIGHT or Walk.LEFT
  w:joint_angles(q, sensors, dt, (cur.shift > 0.5) and sside or nil)
  w:update_com_offset(q, 0.3)
  local legk = w.legs[kside]
  add_pitch(w, q, legk[3], cur.hip)
  add_pitch(w, q, legk[4], cur.knee)
  add_pitch(w, q, legk[5], cur.ankle)
  -- the arms (the walk config's arms.<side>.pitch joints; a body without them skips this)
  local karm, sarm = w.arms[left and 'l' or 'r'], w.arms[left and 'r' or 'l']
  if karm and karm.pitch then add_pitch(w, q, karm.pitch, cur.arm + cur.arms) end
  if sarm and sarm.pitch then add_pitch(w, q, sarm.pitch, cur.arms - cur.arm) end
  -- the torso's pitch that the support leg's measured angles give with its foot flat on the
  -- ground: the fall detection compares the IMU with it (the kick tilts the torso on purpose, fast;
  -- a real fall tips the support foot, and then the two part)
  local pos = sensors and sensors.position
  if pos then
    local qleg, legs = self.qleg, w.legs[sside]
    for k = 1, 6 do qleg[k] = pos[legs[k]] end
    self.fk = w.model:leg_fk(left and 'r' or 'l', qleg, self.fk)
    self.pitch = -self.fk[5]
  else
    self.pitch = tp
  end
  return self.done
end

-- The motion state of a kick with the foot on `side` ('left' or 'right'): the kick, then stance.
function M.state(side)
  local name = 'kick_' .. side
  return {
    entry = function(c)
      c.kick:start(side, c.t)
      if c.want == name then c.want = 'stand' end
    end,
    update = function(c)
      local done = c.kick:update(c.t, c.q, c.sensors, c.dt)
      c.tilt = c.kick.pitch - c.p.bodyTilt
      c:head_angles(c.q)
      c:set_hardness(c.p.hardnessLegs, c.p.hardnessArms, c.p.hardnessHead)
      if done then return 'done' end
    end,
    exit = function(c) c.tilt = 0 end,
    owns = { 'legs', 'arms', 'head' },
  }
end

return M
