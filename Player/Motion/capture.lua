-- The capture point's error for the step adjustment (Player/Motion/step_adjust.lua): where the
-- robot's capture point is against where the walk plans it, heading frame (m), from the IMU.
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
-- The activation (w.cp_gate, per axis 0..1): how much of the error the push recovery acts on (the
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

local G = 9.81

-- The activation for an error's magnitude a (m) between from and full (m): 0 at or below from, 1 at
-- or beyond full, a smoothstep between (no jolt to the joints as the push grows).
function M.activation(a, from, full)
  if full <= 0 or a >= full then return 1 end
  if a <= from then return 0 end
  local u = (a - from) / (full - from)
  return u * u * (3 - 2 * u)
end

-- w.cp_gate from w.cp_err and the config (w.cp_latch: the hold's share, per axis)
local function gate(w, sa, e, dt)
  local g = w.cp_gate or { 1, 1 }
  w.cp_gate = g
  local from, full = sa and rawget(sa, 'activateFrom'), sa and rawget(sa, 'activateFull')
  if not from or not full then g[1], g[2] = 1, 1 return end
  local hold = rawget(sa, 'activateHold') or 0
  local l = w.cp_latch or { 0, 0 }
  w.cp_latch = l
  for i = 1, 2 do
    local gi = M.activation(abs(e[i]), from[i], full[i])
    if hold > 0 then
      if gi >= 1 then l[i] = 1 else l[i] = math.max(0, l[i] - (dt or 0) / hold) end
      if l[i] > gi then gi = l[i] end
    end
    g[i] = gi
  end
end

-- Updates w.cp_err (and w.cp_vel: the accelerometer's velocity error) from sensors (angle, acc)
-- and the gyro's rates (rad/s, torso frame) for one tick of dt s.
function M.update(w, sensors, gyro, dt)
  local angle = sensors.angle
  if not angle then return end
  local p = w.p
  local h = p.tZmp * p.tZmp * G
  local e = w.cp_err or { 0, 0 }
  w.cp_err = e
  local roll, pitch = angle[1], angle[2]
  local tp, tr = pitch - p.bodyTilt, roll
  -- positive pitch tips the top forward (+x), positive roll tips it to the right (-y)
  local px, py = h * sin(tp), -h * sin(tr)
  local vx, vy = h * gyro[2], -h * gyro[1]
  local sa = rawget(p, 'stepAdjust')
  local leak = sa and rawget(sa, 'velocityLeak') or 0
  local acc = sensors.acc
  local v = w.cp_vel or { 0, 0 }
  w.cp_vel = v
  if leak > 0 and acc and dt and dt > 0 and w.active then
    -- specific force into the world (R = Rz Ry Rx), gravity off; horizontal part in the heading frame
    local cr, sr, cp, sp = cos(roll), sin(roll), cos(pitch), sin(pitch)
    local ax, ay, az = acc[1], acc[2], acc[3]
    local y1, z1 = cr * ay - sr * az, sr * ay + cr * az
    local hx = cp * ax + sp * z1
    local hy = y1
    -- the planned COM's velocity in the heading frame (the walk's ground frame turned by its heading)
    local comd = w.comd
    local pv = w.cp_plan_v or { 0, 0 }
    w.cp_plan_v = pv
    local c, s = cos(-w.uTorso[3]), sin(-w.uTorso[3])
    local qx, qy = c * comd[1] - s * comd[2], s * comd[1] + c * comd[2]
    -- the plan's acceleration from its velocity (the heading frame's turn over a tick is small)
    local pax, pay = (qx - pv[1]) / dt, (qy - pv[2]) / dt
    if not w.cp_plan_ok then pax, pay = 0, 0 end
    pv[1], pv[2], w.cp_plan_ok = qx, qy, true
    local k = dt / leak
    v[1] = v[1] + (hx - pax) * dt - k * v[1]
    v[2] = v[2] + (hy - pay) * dt - k * v[2]
    if abs(v[1]) > abs(vx) then vx = v[1] end
    if abs(v[2]) > abs(vy) then vy = v[2] end
  else
    v[1], v[2], w.cp_plan_ok = 0, 0, false
  end
  e[1] = px + p.tZmp * vx
  e[2] = py + p.tZmp * vy
  gate(w, sa, e, dt)
end

return M
