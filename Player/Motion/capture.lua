-- The capture point's error for the step adjustment (Player/Motion/step_adjust.lua): where the
-- robot's capture point is against where the walk plans it, heading frame (m), from the IMU. A walk
-- extension (Player/Motion/walk.lua's stages `sense` and `feedback`):
--
--   local cap = require('Motion.capture').new()
--   w:extend(cap)      -- cap.err: the error { x, y } (nil until the IMU gave an angle), cap.gate:
--                      -- the activation { x, y }
--
-- The error on the ankles and hips (the walk config's feedback.capture and captureHip, rad per m:
-- { roll, pitch }) is this extension's feedback stage.
--
-- Two parts, the COM's position error and its velocity error times tZmp (the capture point of the
-- linear inverted pendulum, c + tZmp c'):
--  * position: the torso's tilt (roll, pitch - bodyTilt) times the COM's height (h = g tZmp^2);
--  * velocity: the torso's tilt rate times h (a robot tipping about its foot), and, with
--    `stepAdjust.velocityLeak` > 0, the accelerometer's: a push moves the body sideways before it
--    tips it (the legs give at the hips and ankles), which the tilt does not see. The accelerometer
--    (specific force, torso frame) turned into the world by the IMU's angles, gravity removed, in
--    the heading frame, is integrated into the velocity's error against the walk's planned COM
--    velocity (w.comd); the integral leaks with velocityLeak (s), so that an offset of the sensor
--    or the plan's own error does not wind it up. The larger of the two velocity errors (by
--    magnitude, per axis) counts: the tilt rate reacts first to a tip, the accelerometer to a shove.
-- The integral rests while the walk stands (no plan to compare with).
--
-- The activation (cap.gate, per axis 0..1): how much of the error the push recovery acts on (the
-- capture feedback on the ankles and hips, the step adjustment's landing). Normal walking, turning
-- and dribbling have an error too (the plan's own mismatch, the sensors'): on the OP3 |ey| < 0.03 m
-- in 99% of the ticks it walks in the scoring scenario and < 0.042 m in 99.9%, while a push of
-- 1.0-2.0 N s passes 0.05 m within 0.05-0.1 s (Tools/plot/capture_stats.py). The gate is 0 below
-- `stepAdjust.activateFrom` (m, { x, y }), 1 beyond `activateFull`, smooth between; a body without
-- them, or with activateFull 0 on an axis: 1 (the dead bands alone). With `activateHold` (s) > 0,
-- once the error has reached activateFull the gate stays at least at 1 - (time since) / hold: the
-- recovery's steps bring the error back into the band while the push is not yet caught.
local sin, cos, abs = math.sin, math.cos, math.abs

local M = {}
local Capture = {}
Capture.__index = Capture

local G = 9.81

-- The estimate's state lives here (err, gate; vel: the accelerometer's velocity error; latch: the
-- hold's share per axis; plan_v, plan_ok: the planned COM velocity of the last tick).
function M.new() return setmetatable({}, Capture) end

-- The activation for an error's magnitude a (m) between from and full (m): 0 at or below from, 1 at
-- or beyond full, a smoothstep between (no jolt to the joints as the push grows).
function M.activation(a, from, full)
  if full <= 0 or a >= full then return 1 end
  if a <= from then return 0 end
  local u = (a - from) / (full - from)
  return u * u * (3 - 2 * u)
end

-- self.gate from the error e and the config (self.latch: the hold's share, per axis)
local function gate(self, sa, e, dt)
  local g = self.gate or { 1, 1 }
  self.gate = g
  local from, full, hold = sa.activateFrom, sa.activateFull, sa.activateHold
  local l = self.latch or { 0, 0 }
  self.latch = l
  for i = 1, 2 do
    local gi = M.activation(abs(e[i]), from[i], full[i])
    if hold > 0 then
      if gi >= 1 then l[i] = 1 else l[i] = math.max(0, l[i] - (dt or 0) / hold) end
      if l[i] > gi then gi = l[i] end
    end
    g[i] = gi
  end
end

-- Stage `sense` of walk w: updates self.err (and self.vel: the accelerometer's velocity error)
-- from sensors (angle, acc) and the gyro's rates (rad/s, torso frame) for one tick of dt s.
function Capture:sense(w, sensors, gyro, dt)
  local angle = sensors.angle
  if not angle then return end
  local p = w.p
  local h = p.tZmp * p.tZmp * G
  local e = self.err or { 0, 0 }
  self.err = e
  local roll, pitch = angle[1], angle[2]
  local tp, tr = pitch - p.bodyTilt, roll
  -- positive pitch tips the top forward (+x), positive roll tips it to the right (-y)
  local px, py = h * sin(tp), -h * sin(tr)
  local vx, vy = h * gyro[2], -h * gyro[1]
  local sa = p.stepAdjust
  local leak = sa.velocityLeak
  local acc = sensors.acc
  local v = self.vel or { 0, 0 }
  self.vel = v
  if leak > 0 and acc and dt and dt > 0 and w.active then
    -- specific force into the world (R = Rz Ry Rx), gravity off; horizontal part in the heading frame
    local cr, sr, cp, sp = cos(roll), sin(roll), cos(pitch), sin(pitch)
    local ax, ay, az = acc[1], acc[2], acc[3]
    local y1, z1 = cr * ay - sr * az, sr * ay + cr * az
    local hx = cp * ax + sp * z1
    local hy = y1
    -- the planned COM's velocity in the heading frame (the walk's ground frame turned by its heading)
    local comd = w.comd
    local pv = self.plan_v or { 0, 0 }
    self.plan_v = pv
    local c, s = cos(-w.uTorso[3]), sin(-w.uTorso[3])
    local qx, qy = c * comd[1] - s * comd[2], s * comd[1] + c * comd[2]
    -- the plan's acceleration from its velocity (the heading frame's turn over a tick is small)
    local pax, pay = (qx - pv[1]) / dt, (qy - pv[2]) / dt
    if not self.plan_ok then pax, pay = 0, 0 end
    pv[1], pv[2], self.plan_ok = qx, qy, true
    local k = dt / leak
    v[1] = v[1] + (hx - pax) * dt - k * v[1]
    v[2] = v[2] + (hy - pay) * dt - k * v[2]
    if abs(v[1]) > abs(vx) then vx = v[1] end
    if abs(v[2]) > abs(vy) then vy = v[2] end
  else
    v[1], v[2], self.plan_ok = 0, 0, false
  end
  e[1] = px + p.tZmp * vx
  e[2] = py + p.tZmp * vy
  gate(self, sa, e, dt)
end

local function deadband(x, d)
  if x > d then return x - d elseif x < -d then return x + d end
  return 0
end

-- Stage `feedback` of walk w: the capture point's error on the ankles and hips (the ankle and hip
-- strategies): a shove shows there before the torso tips (feedback.capture and captureHip, rad per
-- m: { roll, pitch }; pushed left, the ZMP goes left); only while stepping (at stance the tilt's
-- share of the error on the ankles rocked the standing OP3 until it crept away, 1.6 m in 60 s) and
-- beyond the step adjustment's dead band (the walk's own sway, on them, slowed the OP3's sideways
-- walk by a third), times the activation (0 for the errors of normal walking, 1 for a push's).
-- extra: { ankle x, ankle y, hip x, hip y } (the ankles' added to, the hips' set).
function Capture:feedback(w, support, extra)
  local p = w.p
  local fb = p.feedback
  local kc, kh, e, ga = fb.capture, fb.captureHip, self.err, self.gate
  local sa = p.stepAdjust
  if e and not support and w.active then
    local ex, ey = deadband(e[1], sa.deadband[1]), deadband(e[2], sa.deadband[2])
    if ga then ex, ey = ga[1] * ex, ga[2] * ey end
    extra[1], extra[2] = extra[1] - kc[1] * ey, extra[2] + kc[2] * ex
    extra[3], extra[4] = -kh[1] * ey, kh[2] * ex
  end
end

M.Capture = Capture
return M
