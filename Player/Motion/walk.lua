-- Omnidirectional ZMP walk: velocity command (vx, vy, va) -> foot and torso trajectories -> joint angles.
--
-- Step by step, no preview window. At the start of every step the swing foot's landing pose is
-- chosen from the (rate-limited) velocity, the ZMP is laid out as three linear pieces (double
-- support: from the COM's start to the support foot; single support: on the support foot; double
-- support: to the COM's end point midway between the feet) and the linear inverted pendulum is
-- solved analytically for it along x and y (Player/Motion/lipm.lua). During the step the swing foot
-- follows a quintic in the ground plane and a smooth lift. The torso origin is placed so that the
-- whole-body centre of mass (from the mass model) follows the planned COM (plus `com_shift`, the
-- balance feedback's: Player/Motion/balance.lua); leg IK gives the angles.
-- Feedback (all gains in the config): torso rate (gyro) on ankles, knees, hips and arms; torso
-- angle estimated from the support leg's measured joint angles (proprioception) on the hips; the
-- feet's F/T sensors through `com_shift` (Player/Motion/balance.lua, an extension: see below).
--
-- Frames: poses u = {x, y, a} in the walk's ground frame (odometry: starts at 0 where the walk
-- was created). Feet are the foot frames of Lib/kinematics (sole point below the ankle).
-- Every parameter is read from the params table at each step/tick, so a change lands while walking.
--
-- Extensions (Player/Motion/capture.lua, step_adjust.lua, walk_kick.lua, balance.lua; added in
-- order by Player/Motion/control.lua) plug into the walk through named stages: a table with any of
-- the stage functions below, added with w:extend(ext); each stage runs its extensions in the order
-- they were added. A stage gets the extension, the walk (to read: p, vel, stopping, active, dt, T,
-- ph1, ph2, com, comd, zmp, uTorso, uLeft, uRight, legs, ax, ay, arms; counters may be added to
-- w.stats) and the outputs it may change; an extension writes no other field of the walk.
--   shift_com(ext, w, sensors, dt, shift)  update_com_shift(), before advance(): shift = { x, y } (m,
--                                          ground frame) added to the planned COM (Motion.balance)
--   support(ext, w, support) -> support    a step begins: the foot that carries it (LEFT/RIGHT)
--   begin_step(ext, w, step)               a step begins, its nominal plan made: may change
--                                          step.target (the swing foot's landing), step.zmp (the
--                                          single-support ZMP point), step.T, step.ph1, step.ph2
--   retarget(ext, w, step, t, s)           each tick of a step before the swing foot moves (t: s into
--                                          the step, s: the swing's progress 0..1): may replace
--                                          step.start and step.target (the swing goes from one to the
--                                          other), end the step early at step.t_end, set step.z
--   swing(ext, w, step, t)                 each tick of a step after the swing foot moved: may move
--                                          step.foot (its pose, in place) and set step.z
--   pitch(ext, w) -> rad                   the torso's pitch added to bodyTilt (placement, tilt feedback)
--   joints(ext, w, q)                      joint_angles(): offsets into q after the leg IK and the arms
--   sense(ext, w, sensors, gyro, dt)       joint_angles() with sensors, before the feedback
--   feedback(ext, w, support, extra)       then: extra = { ankle x, ankle y, hip x, hip y } (rad about
--                                          the torso's axes) on the support leg's feedback
--   level(ext, w, q, sensors, dt, sup)     after the feedback (not under a kick that names its support
--                                          leg): offsets into q; sup: the support leg in single support
-- step (w.step, the step under way): left (true: the left foot swings), stance (the support foot's
-- pose), start and target (the swing foot's start and landing), foot (the swing foot's pose now),
-- zmp, T, ph1, ph2, t_end (nil: T), z (the swing foot's height).
local lipm = require('Motion.lipm')

local sin, cos, atan2, asin = math.sin, math.cos, math.atan2, math.asin
local abs, pi = math.abs, math.pi

local M = {}
local Walk = {}
Walk.__index = Walk

local LEFT, RIGHT = 0, 1
M.LEFT, M.RIGHT = LEFT, RIGHT

local function clamp(x, lo, hi) if x < lo then return lo elseif x > hi then return hi end return x end
local function wrap(a) return (a + pi) % (2 * pi) - pi end
M.wrap = wrap

-- u (+) d: d given in u's frame.
local function pose_global(d, u)
  local c, s = cos(u[3]), sin(u[3])
  return { u[1] + c * d[1] - s * d[2], u[2] + s * d[1] + c * d[2], wrap(u[3] + d[3]) }
end
-- u expressed in the frame of u0.
local function pose_relative(u, u0)
  local c, s = cos(u0[3]), sin(u0[3])
  local dx, dy = u[1] - u0[1], u[2] - u0[2]
  return { c * dx + s * dy, -s * dx + c * dy, wrap(u[3] - u0[3]) }
end
local function interp(t, u1, u2)
  return { u1[1] + t * (u2[1] - u1[1]), u1[2] + t * (u2[2] - u1[2]), wrap(u1[3] + t * wrap(u2[3] - u1[3])) }
end
M.pose_global, M.pose_relative, M.interp = pose_global, pose_relative, interp

local function copy3(dst, src) dst[1], dst[2], dst[3] = src[1], src[2], src[3] return dst end
local function set3(dst, a, b, c) dst[1], dst[2], dst[3] = a, b, c return dst end
local function interp_into(out, t, u1, u2)
  out[1], out[2] = u1[1] + t * (u2[1] - u1[1]), u1[2] + t * (u2[2] - u1[2])
  out[3] = wrap(u1[3] + t * wrap(u2[3] - u1[3]))
  return out
end

-- quintic 0..1 with zero velocity and acceleration at both ends
local function smooth(t) return t * t * t * (10 + t * (-15 + 6 * t)) end

-- 0..1 at constant rate between ramps of fraction r at either end (zero rate at both ends; the
-- peak rate is 1 / (1 - r) of the mean)
function M.trapezoid(u, r)
  u = clamp(u, 0, 1)
  if r <= 0 then return u end
  local v = 1 / (1 - r) -- peak rate
  if u < r then return 0.5 * v * u * u / r end
  if u > 1 - r then local w = 1 - u return 1 - 0.5 * v * w * w / r end
  return 0.5 * v * r + v * (u - r)
end

-- Foot pose (ground frame, flat, height z) in the torso frame: torso at (tx, ty, tz), yaw ta,
-- pitch tp, roll tr (small). Writes {x, y, z, roll, pitch, yaw} into out.
local function foot_in_torso(out, fx, fy, fz, fa, tx, ty, tz, ta, tp, tr)
  local dx, dy, dz = fx - tx, fy - ty, fz - tz
  local c, s = cos(ta), sin(ta)
  local x1, y1 = c * dx + s * dy, -s * dx + c * dy
  -- undo pitch (Ry(-tp))
  local cp, sp = cos(tp), sin(tp)
  local x2, z2 = x1 * cp - dz * sp, x1 * sp + dz * cp
  -- undo roll (Rx(-tr))
  local cr, sr = cos(tr), sin(tr)
  local y3, z3 = y1 * cr + z2 * sr, -y1 * sr + z2 * cr
  out[1], out[2], out[3] = x2, y3, z3
  -- orientation Rx(-tr) Ry(-tp) Rz(d) as z-y-x angles
  local d = wrap(fa - ta)
  local cd, sd = cos(d), sin(d)
  -- R = Ry(-tp) Rz(d)
  -- (first row: cp*cd, -cp*sd, -sp; second: sd, cd, 0; third: sp*cd, -sp*sd, cp)
  local r11 = cp * cd
  local r21, r22, r23 = sd, cd, 0
  local r31, r32, r33 = sp * cd, -sp * sd, cp
  -- R' = Rx(-tr) R: only rows 2 and 3 change
  local q21 = cr * r21 + sr * r31
  local q31, q32, q33 = -sr * r21 + cr * r31, -sr * r22 + cr * r32, -sr * r23 + cr * r33
  out[4] = atan2(q32, q33)
  out[5] = asin(clamp(-q31, -1, 1))
  out[6] = atan2(q21, r11)
  return out
end
M.foot_in_torso = foot_in_torso

-- Creates a walk. params: the walk config table (read live); model: a Lib/kinematics model (may be
-- nil for trajectory-only use: then joint angles are not computed).
function M.new(params, model)
  local w = setmetatable({ p = params, model = model }, Walk)
  w.vel = { 0, 0, 0 }      -- current (rate-limited) velocity, m/s and rad/s
  w.cmd = { 0, 0, 0 }      -- commanded velocity
  w.cx, w.cy = {}, {}      -- LIPM coefficients of the current step
  w.lpose, w.rpose = {}, {}
  w.q = {}
  w.com_offset = { 0, 0 }  -- whole-body COM minus torso origin, torso frame (from the mass model)
  w.gyro_f = { 0, 0, 0 }
  w.fb = { 0, 0, 0, 0 }    -- torso-angle feedback state (roll, pitch) filtered
  w.stats = { steps = 0 }
  w.vel_eff = { 0, 0, 0 }
  w.va_correction = 0      -- rad/s added to the turning of each step (heading feedback)
  w.com_shift = { 0, 0 }   -- m, ground frame: added to the planned COM (balance feedback, Motion.balance)
  w.step = {}              -- the step under way, as the extensions see it (see the header)
  w.feedback_extra = { 0, 0, 0, 0 } -- the extensions' feedback of the tick (see the header)
  w.extensions, w.stages = {}, {}
  for _, stage in ipairs(M.STAGES) do w.stages[stage] = {} end
  w:reset()
  return w
end

M.STAGES = { 'shift_com', 'support', 'begin_step', 'retarget', 'swing', 'pitch', 'joints', 'sense', 'feedback',
  'level' }

-- Adds an extension (see the header): its stages run after those of the extensions added before.
function Walk:extend(ext)
  local any = false
  for _, stage in ipairs(M.STAGES) do
    local f = ext[stage]
    if f ~= nil then
      if type(f) ~= 'function' then error(string.format("walk extension: stage '%s' must be a function", stage), 2) end
      local list = self.stages[stage]
      list[#list + 1] = ext
      any = true
    end
  end
  if not any then error('walk extension: no stage (' .. table.concat(M.STAGES, ', ') .. ')', 2) end
  self.extensions[#self.extensions + 1] = ext
  return ext
end

-- The torso's pitch the extensions add to bodyTilt (rad; a kick out of the walk leans it on purpose).
function Walk:extra_pitch()
  local a = 0
  for _, ext in ipairs(self.stages.pitch) do a = a + ext:pitch(self) end
  return a
end

-- Before advance(): the COM shift of this tick from the extensions (sensors of the tick, dt s).
function Walk:update_com_shift(sensors, dt)
  for _, ext in ipairs(self.stages.shift_com) do ext:shift_com(self, sensors, dt, self.com_shift) end
end

-- Puts the walk at stance at the origin of its ground frame (feet at the nominal spacing).
function Walk:reset(u)
  u = u or { 0, 0, 0 }
  local p = self.p
  -- the current poses are tables of their own (filled in place every tick, no garbage); the
  -- step's start and end poses are replaced by new tables at each step
  self.uTorso = { u[1], u[2], u[3] }
  self.uLeft = pose_global({ 0, p.footY, 0 }, u)
  self.uRight = pose_global({ 0, -p.footY, 0 }, u)
  self.uLeft1, self.uLeft2 = { unpack(self.uLeft) }, { unpack(self.uLeft) }
  self.uRight1, self.uRight2 = { unpack(self.uRight) }, { unpack(self.uRight) }
  self.uTorso1, self.uTorso2 = { u[1], u[2], u[3] }, { u[1], u[2], u[3] }
  self.com = { self.uTorso[1], self.uTorso[2] }
  self.comd = { 0, 0 }
  self.zmp = { self.uTorso[1], self.uTorso[2] }
  self.active = false
  self.stopping = false
  self.t = 0
  self.T = nil             -- s, the duration of the step under way (latched at its start)
  self.support = RIGHT
  self.ph = 0
  self.swing_z = 0
  self.vel[1], self.vel[2], self.vel[3] = 0, 0, 0
end

local function finite(v) return type(v) == 'number' and v == v and v ~= math.huge and v ~= -math.huge end

-- Clamps a velocity to the limits of the config; NaN/inf refused (returns nil, message).
function M.clamp_velocity(p, vx, vy, va)
  if not finite(vx) or not finite(vy) or not finite(va) then
    return nil, 'walk velocity must be finite numbers'
  end
  vx = clamp(vx, p.velLimitX[1], p.velLimitX[2])
  vy = clamp(vy, p.velLimitY[1], p.velLimitY[2])
  va = clamp(va, p.velLimitA[1], p.velLimitA[2])
  -- combined commands share one budget: the fractions of the limits add up to at most 1
  -- (fast forward and fast turning at once is more than the feet can do)
  local fx = vx >= 0 and vx / p.velLimitX[2] or vx / -p.velLimitX[1]
  local fy = vy >= 0 and vy / p.velLimitY[2] or vy / -p.velLimitY[1]
  local fa = va >= 0 and va / p.velLimitA[2] or va / -p.velLimitA[1]
  local n = abs(fx) + abs(fy) + abs(fa)
  if n > 1 then vx, vy, va = vx / n, vy / n, va / n end
  return vx, vy, va
end

-- The duration of a step at velocity v: tStep, shortened towards `turnStep.tStep` as the turning
-- rate |v[3]| rises from turnStep.va[1] to turnStep.va[2] (rad/s; the feet's relative yaw is bounded
-- by the legs, so a faster turn takes more steps, not larger ones); `turnStep` false: tStep.
function M.step_period(p, v)
  local T = p.tStep
  local ts = p.turnStep
  if ts and v then
    local f = clamp((abs(v[3]) - ts.va[1]) / (ts.va[2] - ts.va[1]), 0, 1)
    T = T + f * (ts.tStep - T)
  end
  return T
end

-- The duration of a step at velocity v (default: the walk's). The analytic engine takes the period
-- as it is; an engine that plans on its own sample grid (Motion.walk_preview) rounds it to whole ticks.
function Walk:step_time(v) return M.step_period(self.p, v or self.vel) end

function Walk:set_velocity(vx, vy, va)
  local cx, cy, ca = M.clamp_velocity(self.p, vx, vy, va)
  if not cx then return nil, cy end
  self.cmd[1], self.cmd[2], self.cmd[3] = cx, cy, ca
  return cx, cy, ca
end

function Walk:start()
  if not self.active then
    self.active = true
    self.t = self:step_time() -- a new step begins at the next update
    self.T = nil
    self.stepping = false
    self.support = nil
    self.steps_still = 0
    self.step.t_end = nil
  end
  self.stopping = false
end

function Walk:stop() if self.active then self.stopping = true end end
function Walk:is_active() return self.active end

-- Swing foot target for the step, given the support foot and the velocity.
function Walk:step_target(support_u, swing_left, v)
  local p = self.p
  local T = self:step_time(v)
  local sgn = swing_left and 1 or -1
  local dx = v[1] * T
  -- sideways and turning: the foot on the side of the motion takes the whole step, the other returns
  local dy, da = 0, 0
  if (v[2] > 0) == swing_left and v[2] ~= 0 then dy = 2 * v[2] * T end
  -- turning: each step turns the swing foot by the turn of two steps against the support foot; the
  -- closing foot lands toed in by `turnToeIn` x a step's turn (the opening one opens that much less),
  -- so the feet's relative yaw swings about zero (the OP3's legs touch beyond about 0.5 rad toed out
  -- or in, Tools/tune/hip_yaw_clearance.py: opening from parallel alone met them at 1.1 rad/s)
  if v[3] ~= 0 then
    local closing = p.turnToeIn * v[3] * T
    da = (v[3] > 0) == swing_left and 2 * v[3] * T - closing or closing
  end
  -- the support foot turned: keep forward steps along the mean heading
  local rel = { dx, sgn * 2 * p.footY + dy, da }
  rel[1] = clamp(rel[1], p.stepLimitX[1], p.stepLimitX[2])
  -- lateral: never closer than the minimum spacing, never further than the maximum
  local ay = sgn * rel[2]
  ay = clamp(ay, p.stepLimitY[1], p.stepLimitY[2])
  rel[2] = sgn * ay
  local aa = sgn * rel[3]
  aa = clamp(aa, p.stepLimitA[1], p.stepLimitA[2])
  rel[3] = sgn * aa
  -- turning feet: move the foot's ankle point so that the feet turn about the midpoint
  local half = sgn * p.footY
  rel[1] = rel[1] - half * sin(rel[3])
  rel[2] = rel[2] - half * (1 - cos(rel[3]))
  M.clear_feet(p, rel, sgn)
  return pose_global(rel, support_u)
end

-- A turned foot swings its inner heel or toe into the other foot (OP3 at 1 rad: 2.5 cm of
-- overlap): the landing moves outward until the inner corners of each sole keep `footClearance` (m)
-- from the other sole's inner edge. rel: the swing foot in the support foot's frame (changed in
-- place), sgn: +1 for the left foot swinging. The soles from the walk config's `sole` (toe, heel:
-- m ahead of and behind the ankle point; inner: m from the ankle point to the inner edge); a body
-- with `sole` false is not checked.
function M.clear_feet(p, rel, sgn)
  local sole = p.sole
  if not sole then return end
  local c, s = cos(rel[3]), sin(rel[3])
  local need = sole.inner + p.footClearance
  -- the swing sole's inner corners in the support frame, against the support sole's inner edge
  local shift = 0
  for _, x in ipairs({ sole.toe, -sole.heel }) do
    shift = math.max(shift, need - sgn * (rel[2] + s * x - c * sgn * sole.inner))
  end
  rel[2] = rel[2] + sgn * shift
  -- the support sole's inner corners in the swing frame, against the swing sole's inner edge where
  -- they lie along its length (a few small moves: each changes where the corners lie)
  for _ = 1, 4 do
    local more = 0
    for _, x in ipairs({ sole.toe, -sole.heel }) do
      local dx, dy = x - rel[1], sgn * sole.inner - rel[2]
      local xs, ys = c * dx + s * dy, -s * dx + c * dy
      if xs < sole.toe + p.footClearance and xs > -sole.heel - p.footClearance then
        more = math.max(more, need + sgn * ys)
      end
    end
    if more <= 1e-4 then break end
    rel[2] = rel[2] + sgn * more
  end
end

-- rate-limits the current velocity towards the command over one step
function Walk:update_velocity(v, stopping)
  local p = self.p
  v = v or self.vel
  local T = self:step_time(v)
  local c = self.cmd
  local tx, ty, ta = c[1], c[2], c[3]
  if stopping == nil then stopping = self.stopping end
  if stopping then tx, ty, ta = 0, 0, 0 end
  local acc = p.accLimit
  v[1] = v[1] + clamp(tx - v[1], -acc[1] * T, acc[1] * T)
  v[2] = v[2] + clamp(ty - v[2], -acc[2] * T, acc[2] * T)
  v[3] = v[3] + clamp(ta - v[3], -acc[3] * T, acc[3] * T)
end

-- True when the feet stand at the nominal spacing (stop allowed).
function Walk:feet_together()
  local rel = pose_relative(self.uLeft2, self.uRight2)
  local p = self.p
  return abs(rel[1]) < 1e-3 and abs(rel[2] - 2 * p.footY) < 1e-3 and abs(rel[3]) < 1e-3
end

-- The extensions' stages of a step's start (see the header): the swing foot's start and landing,
-- the ZMP point and the timing of the step as they leave them.
local function extend_step(self, step)
  for _, ext in ipairs(self.stages.begin_step) do ext:begin_step(self, step) end
  if step.left then self.uLeft1, self.uLeft2 = step.start, step.target
  else self.uRight1, self.uRight2 = step.start, step.target end
  self.uSupport = step.zmp
end

function Walk:begin_step()
  local p = self.p
  local step = self.step
  self.uLeft1, self.uRight1 = self.uLeft2, self.uRight2
  self.uTorso1 = self.uTorso2
  -- a step ended early (step adjustment's touch-down): the next one starts from the COM's plan now
  if step.t_end then self.uTorso1 = { self.com[1], self.com[2], self.uTorso[3] } end
  step.t_end = nil
  self:update_velocity()
  local v = self.vel
  local still = abs(v[1]) < 1e-4 and abs(v[2]) < 1e-4 and abs(v[3]) < 1e-4
  if self.stopping and still and self:feet_together() and self.support ~= nil and self.steps_still >= 1 then
    self.active = false
    self.stopping = false
    copy3(self.uTorso, self.uTorso2)
    return false
  end
  self.steps_still = still and (self.steps_still or 0) + 1 or 0
  -- alternate the support foot; the first step swings the foot on the side of the motion
  if self.support == nil then
    local lead_left = v[2] > 0 or (v[2] == 0 and self.cmd[2] > 0) or (self.cmd[2] == 0 and self.cmd[3] > 0)
    self.support = lead_left and RIGHT or LEFT
  else
    self.support = 1 - self.support
  end
  -- a push sideways: the foot on its side swings (Motion.step_adjust)
  for _, ext in ipairs(self.stages.support) do self.support = ext:support(self, self.support) end
  local sY = p.supportY
  -- heading correction from outside (IMU yaw against the commanded turning), rad/s
  local ve = self.vel_eff
  ve[1], ve[2], ve[3] = v[1], v[2], v[3] + self.va_correction
  v = ve
  local T = self:step_time(v)
  if self.support == LEFT then
    self.uRight2 = self:step_target(self.uLeft1, false, v)
    self.uLeft2 = self.uLeft1
    self.uSupport = pose_global({ p.supportX, sY, 0 }, self.uLeft1)
  else
    self.uLeft2 = self:step_target(self.uRight1, true, v)
    self.uRight2 = self.uRight1
    self.uSupport = pose_global({ p.supportX, -sY, 0 }, self.uRight1)
  end
  -- the step keeps the duration and single-support phase it was planned with (its COM plan is only
  -- valid for them): a live change of tStep or phSingle (Lib/param.lua) lands at the next step;
  -- an extension may move the landing (Motion.step_adjust) or make the step its own (a kick out of
  -- the walk: Motion.walk_kick)
  local left = self.support ~= LEFT
  step.left = left
  step.stance = left and self.uRight1 or self.uLeft1
  step.start = left and self.uLeft1 or self.uRight1
  step.target = left and self.uLeft2 or self.uRight2
  step.foot = left and self.uLeft or self.uRight
  step.zmp = self.uSupport
  step.T, step.ph1, step.ph2 = T, p.phSingle[1], p.phSingle[2]
  extend_step(self, step)
  local mid = interp(0.5, self.uLeft2, self.uRight2)
  self.uTorso2 = pose_global({ p.supportX, 0, 0 }, mid)
  T = step.T
  self.T, self.ph1, self.ph2 = T, step.ph1, step.ph2
  self:plan_com(T, self.ph1 * T, self.ph2 * T)
  self.stats.steps = self.stats.steps + 1
  return true
end

-- The COM over the step that begins (engine-specific): the analytic engine solves the linear
-- inverted pendulum for the step's piecewise-linear ZMP, from uTorso1 over uSupport to uTorso2.
function Walk:plan_com(T, t1, t2)
  local p = self.p
  lipm.solve(self.uTorso1[1], self.uSupport[1], self.uTorso2[1], T, t1, t2, p.tZmp, self.cx)
  lipm.solve(self.uTorso1[2], self.uSupport[2], self.uTorso2[2], T, t1, t2, p.tZmp, self.cy)
end

-- At stance: the COM over (x, y), the middle of the feet (an engine may bring it there over time).
function Walk:hold_com(x, y)
  self.com[1], self.com[2], self.comd[1], self.comd[2] = x, y, 0, 0
  self.zmp[1], self.zmp[2] = x, y
end

-- COM position and velocity and the ZMP along x and y at time t of the current step, called once
-- per tick while walking (an engine may advance its own state here).
function Walk:com_at(t)
  local x, xd, zx = lipm.eval(self.cx, t)
  local y, yd, zy = lipm.eval(self.cy, t)
  return x, xd, zx, y, yd, zy
end

-- Advances the walk by dt seconds and computes the foot poses in the torso frame (self.lpose,
-- self.rpose). Returns true while walking.
function Walk:advance(dt)
  local p = self.p
  if self.active then
    local T = self.T or self:step_time()
    -- a step the step adjustment put down early ends with its touch-down
    local t_end = self.step.t_end or T
    self.t = self.t + dt
    if self.t >= t_end - 1e-9 then
      self.t = self.t - t_end
      if self.t < 0 then self.t = 0 end
      if not self:begin_step() then
        self.t = 0
      end
    end
  end
  if not self.active then
    -- stance: COM over the middle of the feet
    local uL, uR = self.uLeft2, self.uRight2
    local a = wrap(uL[3] + 0.5 * wrap(uR[3] - uL[3]))
    local c, sn = cos(a), sin(a)
    local ux = 0.5 * (uL[1] + uR[1]) + c * p.supportX
    local uy = 0.5 * (uL[2] + uR[2]) + sn * p.supportX
    copy3(self.uLeft, uL)
    copy3(self.uRight, uR)
    self:hold_com(ux, uy, dt)
    set3(self.uTorso, self.com[1], self.com[2], a)
    self.ph = 0
    self.swing_z = 0
  else
    local T = self.T
    local t = self.t
    local ph = t / T
    self.ph = ph
    local x, xd, zx, y, yd, zy = self:com_at(t, dt)
    self.com[1], self.com[2], self.comd[1], self.comd[2] = x, y, xd, yd
    self.zmp[1], self.zmp[2] = zx, zy
    local ph1, ph2 = self.ph1, self.ph2
    local phs = clamp((ph - ph1) / (ph2 - ph1), 0, 1)
    -- the foot reaches its landing point a little before touch-down (servo lag)
    -- (after `swingDelay` of single support: the foot lifts before it moves, its toe clears an edge)
    local delay = p.swingDelay
    local s = smooth(clamp((phs - delay) / (p.swingLead - delay), 0, 1))
    local lift = 16 * phs * phs * (1 - phs) * (1 - phs)
    self.swing_z = p.stepHeight * lift
    -- capture point stepping: the landing moves, or the swing foot is put down (Motion.step_adjust)
    local step = self.step
    step.z = self.swing_z
    for _, ext in ipairs(self.stages.retarget) do ext:retarget(self, step, t, s) end
    if step.left then self.uLeft1, self.uLeft2 = step.start, step.target
    else self.uRight1, self.uRight2 = step.start, step.target end
    self.swing_z = step.z
    if self.support == LEFT then
      interp_into(self.uRight, s, self.uRight1, self.uRight2)
      copy3(self.uLeft, self.uLeft1)
    else
      interp_into(self.uLeft, s, self.uLeft1, self.uLeft2)
      copy3(self.uRight, self.uRight1)
    end
    -- the swing foot's turn over the whole single support at a near-constant rate: with the ground
    -- motion's profile a 1 rad turn (2 rad/s) asks the hip yaw for 12 rad/s, its servo gives 4.8
    local ramp = p.swingYawRamp
    if ramp then
      local left = self.support ~= LEFT
      local a1 = left and self.uLeft1[3] or self.uRight1[3]
      local a2 = left and self.uLeft2[3] or self.uRight2[3]
      local sw = left and self.uLeft or self.uRight
      sw[3] = wrap(a1 + M.trapezoid(phs, ramp) * wrap(a2 - a1))
    end
    -- a kick out of the walk swings the foot its own way (Motion.walk_kick)
    for _, ext in ipairs(self.stages.swing) do ext:swing(self, step, t) end
    self.swing_z = step.z
    -- heading: turns at a constant rate over the whole step (no yaw jerk from the swing; a torso
    -- that followed the feet's mean yaw, so that both hips share the swing foot's turn, measured
    -- worse on the OP3: its stop and start in double support slipped the support foot)
    local a1 = wrap(self.uLeft1[3] + 0.5 * wrap(self.uRight1[3] - self.uLeft1[3]))
    local a2 = wrap(self.uLeft2[3] + 0.5 * wrap(self.uRight2[3] - self.uLeft2[3]))
    set3(self.uTorso, x, y, wrap(a1 + ph * wrap(a2 - a1)))
  end
  self:place_feet()
  return self.active
end

-- The foot poses in the torso frame (self.lpose, self.rpose) from the COM, the heading and the feet.
function Walk:place_feet()
  local p = self.p
  -- torso origin from the COM: subtract the COM offset (torso frame, rotated by the heading)
  local ta = self.uTorso[3]
  local ox, oy = self.com_offset[1] + p.footX, self.com_offset[2]
  local c, s = cos(ta), sin(ta)
  local tx = self.com[1] - (c * ox - s * oy) + self.com_shift[1]
  local ty = self.com[2] - (s * ox + c * oy) + self.com_shift[2]
  self.torso_x, self.torso_y = tx, ty
  local lz, rz = 0, 0
  if self.active then
    if self.support == LEFT then rz = self.swing_z else lz = self.swing_z end
  end
  local tz, tp, tr = p.bodyHeight, p.bodyTilt, 0
  for _, ext in ipairs(self.stages.pitch) do tp = tp + ext:pitch(self) end
  local uL, uR = self.uLeft, self.uRight
  foot_in_torso(self.lpose, uL[1], uL[2], lz, uL[3], tx, ty, tz, ta, tp, tr)
  foot_in_torso(self.rpose, uR[1], uR[2], rz, uR[3], tx, ty, tz, ta, tp, tr)
end

-- Support phase weight: 0 in double support, 1 in single support (for feedback and compensation).
function Walk:single_support()
  if not self.active then return 0 end
  local ph = self.ph
  local ph1, ph2 = self.ph1 or self.p.phSingle[1], self.ph2 or self.p.phSingle[2]
  if ph < ph1 or ph > ph2 then return 0 end
  return 1
end

-- Leg angles into q (1-based robot joint order) from the last advance(); returns the IK flags.
function Walk:leg_angles(q)
  return self.model:legs_ik(self.lpose, self.rpose, q)
end

local LEG = { 'hip_yaw', 'hip_roll', 'hip_pitch', 'knee', 'ank_pitch', 'ank_roll' }

-- Joint bookkeeping from the robot config: 1-based indices by name, the leg joints the leg IK
-- drives, the arms' joints from the walk config's `arms` (by name: a body without arms has none),
-- and each of these joints' axis components along x and y (feedback is stated as rotations about
-- the torso's axes). Joints the walk does not drive (a waist) are left alone. `files` names the
-- walk config in errors.
function Walk:bind(robot, files)
  files = files or 'walk config'
  local ji, ax, ay = {}, {}, {}
  for i, name in ipairs(robot.joints) do ji[name] = i end
  self.ji, self.ax, self.ay = ji, ax, ay
  local function axis_of(i, name)
    local a = self.model:axis(name) -- the torso frame at the zero pose, from the description
    ax[i], ay[i] = a[1], a[2]
  end
  -- legs: the model's leg chains (hip yaw to ankle roll); by name without a model
  self.legs = { [LEFT] = {}, [RIGHT] = {} }
  local chains = self.model and self.model.leg_index
  for side, pre in pairs({ [LEFT] = 'l_', [RIGHT] = 'r_' }) do
    for k, j in ipairs(LEG) do
      local i = chains and chains[side][k] or ji[pre .. j]
      if not i then error(string.format("walk: the robot has no leg joint '%s%s' (robot.joints)", pre, j), 2) end
      self.legs[side][k] = i
      axis_of(i, robot.joints[i])
    end
  end
  -- arms: side -> { pitch = index or nil, roll = index or nil, joints = { { index, name }, ... } }
  -- (their form is checked where the walk config is loaded, Config/spec/walk.lua; their joint
  -- names against this body's here)
  self.arms, self.arm_joints = {}, {}
  for side, a in pairs(self.p.arms) do
    local arm = { joints = {} }
    for name in pairs(a.posture) do
      local i = ji[name]
      if not i then
        error(string.format("%s: key 'arms.%s.posture' names unknown joint '%s' (robot.joints)", files, side,
          tostring(name)), 2)
      end
      arm.joints[#arm.joints + 1] = { i, name }
      self.arm_joints[#self.arm_joints + 1] = i
      axis_of(i, name)
    end
    table.sort(arm.joints, function(x, y) return x[1] < y[1] end)
    if a.pitch then arm.pitch = ji[a.pitch] end
    if a.roll then arm.roll = ji[a.roll] end
    self.arms[side] = arm
  end
  table.sort(self.arm_joints)
  self.qleg = {}
  self.pose_meas = {}
  return self
end

-- The hip yaw servos' lag made up: the command leads the plan by `hipYawLead` (s) x its rate (a
-- first-order servo with time constant tau follows q + tau q' without lag), so that a turning swing
-- foot lands turned as planned. Only while stepping (the IK's rate from the previous tick).
function Walk:lead_hip_yaw(q, dt)
  local lead = self.p.hipYawLead
  local prev = self.hip_yaw_prev
  if not prev then prev = {} self.hip_yaw_prev = prev end
  for side = LEFT, RIGHT do
    local i = self.legs[side][1]
    local qi = q[i]
    if lead > 0 and self.active and prev[side] and dt and dt > 0 then
      q[i] = qi + lead * (qi - prev[side]) / dt
    end
    prev[side] = self.active and qi or nil
  end
end

local function deadband(x, d)
  if x > d then return x - d elseif x < -d then return x + d end
  return 0
end

-- adds a rotation (rad) about the torso's x (rx) and y (ry) axes to joint i, through its axis
local function add_rot(self, q, i, rx, ry)
  q[i] = q[i] + self.ax[i] * rx + self.ay[i] * ry
end

-- The stages of joint_angles(), in the order it calls them.

-- Legs by IK from the last advance(), the hip yaw's lead added; returns the IK flags.
local function leg_ik(self, q, dt)
  local flags = self.model:legs_ik(self.lpose, self.rpose, q)
  self:lead_hip_yaw(q, dt)
  return flags
end

-- Arms: the posture by joint name (read live: Walk.set('arms.l.posture.l_el', 0.3) lands at once).
local function arm_posture(self, q)
  local arms = self.p.arms
  for side, arm in pairs(self.arms) do
    local posture = arms[side].posture
    for _, j in ipairs(arm.joints) do q[j[1]] = posture[j[2]] end
  end
end

-- Arm swing against the legs: the arm opposite to the forward foot goes forward.
local function arm_swing(self, q)
  local p, larm, rarm = self.p, self.arms.l, self.arms.r
  if p.armSwing ~= 0 then
    local rel = pose_relative(self.uLeft, self.uRight)
    if larm and larm.pitch then add_rot(self, q, larm.pitch, 0, p.armSwing * rel[1]) end
    if rarm and rarm.pitch then add_rot(self, q, rarm.pitch, 0, -p.armSwing * rel[1]) end
  end
end

-- The extensions' joint offsets (a kick out of the walk: Motion.walk_kick).
local function extension_joints(self, q)
  for _, ext in ipairs(self.stages.joints) do ext:joints(self, q) end
end

-- Which leg carries the robot: the support leg while stepping, both at stance. Returns the
-- single-support weight and the support leg (nil: both).
local function support_leg(self, support)
  local ss = support and 1 or self:single_support()
  local sup = support or (self.active and self.support or nil)
  return ss, sup
end

-- Hip roll compensation of the sag in single support.
local function hip_roll_compensation(self, q, ss, sup)
  if sup ~= nil and ss > 0 then
    local c = self.p.hipRollCompensation * (sup == LEFT and 1 or -1)
    add_rot(self, q, self.legs[sup][2], c, 0)
  end
end

-- The gyro low-passed (self.gyro_f), then its dead band: the rates the feedback acts on.
local function filter_gyro(self, g, dt)
  local fb, gf = self.p.feedback, self.gyro_f
  local alpha = clamp(dt / (dt + fb.gyroTimeConstant), 0, 1)
  gf[1] = gf[1] + alpha * (g[1] - gf[1])
  gf[2] = gf[2] + alpha * (g[2] - gf[2])
  return deadband(gf[1], fb.gyroDeadband[1]), deadband(gf[2], fb.gyroDeadband[2])
end

-- The extensions' view of the sensors (the capture point's error: Motion.capture).
local function extension_sense(self, sensors, g, dt)
  for _, ext in ipairs(self.stages.sense) do ext:sense(self, sensors, g, dt) end
end

-- The extensions' feedback on the ankles (on top of tax, tay) and the hips (the capture point's
-- error: Motion.capture). Returns ankle x, y and hip x, y (rad about the torso's axes).
local function extension_feedback(self, support, tax, tay)
  local extra = self.feedback_extra
  extra[1], extra[2], extra[3], extra[4] = tax, tay, 0, 0
  for _, ext in ipairs(self.stages.feedback) do ext:feedback(self, support, extra) end
  return extra[1], extra[2], extra[3], extra[4]
end

-- Torso angle from proprioception: the support foot is flat, so its measured pose in the torso
-- frame gives the torso's real tilt; the difference from the commanded tilt goes to the hips.
-- Returns the hips' correction about x and y (0, 0 without measured joint angles).
local function torso_estimate(self, sensors, sup, dt, lim)
  local fb = self.p.feedback
  local tx, ty = 0, 0
  local pos = sensors.position
  if pos and fb.torso[1] + fb.torso[2] ~= 0 then
    local side = sup or (self.uLeft[1] > 0 and LEFT or RIGHT)
    local legi = self.legs[side]
    local qleg = self.qleg
    for k = 1, 6 do qleg[k] = pos[legi[k]] end
    local meas = self.model:leg_fk(side == LEFT and 'l' or 'r', qleg, self.pose_meas)
    local cmd = side == LEFT and self.lpose or self.rpose
    local er, ep = cmd[4] - meas[4], cmd[5] - meas[5]
    local fs = self.fb
    local beta = clamp(dt / (dt + fb.torsoTimeConstant), 0, 1)
    fs[1] = fs[1] + beta * (er - fs[1])
    fs[2] = fs[2] + beta * (ep - fs[2])
    tx, ty = clamp(fb.torso[1] * fs[1], -lim, lim), clamp(fb.torso[2] * fs[2], -lim, lim)
  end
  return tx, ty
end

-- The feedback on the support leg (both at stance): gyro rates (gx, gy), tilt and extensions on
-- the ankles (tax, tay) and hips (thx, thy), the torso estimate on the hips (tx, ty); each term
-- within lim.
local function leg_feedback(self, q, sup, gx, gy, tax, tay, thx, thy, tx, ty, lim)
  local fb = self.p.feedback
  local ankx, anky = clamp(fb.ankle[1] * gx + tax, -lim, lim), clamp(fb.ankle[2] * gy + tay, -lim, lim)
  local kny = clamp(fb.knee * gy, -lim, lim)
  local hipx, hipy = clamp(fb.hip[1] * gx + thx, -lim, lim), clamp(fb.hip[2] * gy + thy, -lim, lim)
  for side = LEFT, RIGHT do
    local w = (sup == nil or sup == side) and 1 or 0
    if w > 0 then
      local legi = self.legs[side]
      add_rot(self, q, legi[2], hipx + tx, 0)
      add_rot(self, q, legi[3], 0, hipy + ty)
      add_rot(self, q, legi[4], 0, kny)
      add_rot(self, q, legi[5], 0, anky)
      add_rot(self, q, legi[6], ankx, 0)
    end
  end
end

-- The extensions' corrections after the feedback (the swing foot lands flat on a leaning robot:
-- Motion.step_adjust); sup: the support leg in single support, nil otherwise.
local function extension_level(self, q, sensors, dt, sup)
  for _, ext in ipairs(self.stages.level) do ext:level(self, q, sensors, dt, sup) end
end

-- The gyro rates on the arms' pitch and roll joints.
local function arm_feedback(self, q, gx, gy, lim)
  local fb = self.p.feedback
  local armx, army = clamp(fb.arm[1] * gx, -lim, lim), clamp(fb.arm[2] * gy, -lim, lim)
  for _, arm in pairs(self.arms) do
    if arm.pitch then add_rot(self, q, arm.pitch, 0, army) end
    if arm.roll then add_rot(self, q, arm.roll, armx, 0) end
  end
end

-- All joint angles of the walk into q (1-based robot order): legs by IK from the last advance(),
-- arms from the config, then feedback. sensors: { gyro = {3} rad/s, position = joint angles
-- (1-based, measured) } or nil (no feedback). dt: the tick. support: LEFT/RIGHT to name the leg that
-- carries the robot in single support when the walk is not stepping (kick). Returns the IK flags.
function Walk:joint_angles(q, sensors, dt, support)
  local flags = leg_ik(self, q, dt)
  arm_posture(self, q)
  arm_swing(self, q)
  extension_joints(self, q)
  local ss, sup = support_leg(self, support)
  hip_roll_compensation(self, q, ss, sup)
  if not sensors then return flags end
  local g = sensors.gyro
  local gx, gy = filter_gyro(self, g, dt)
  extension_sense(self, sensors, g, dt)
  local lim = self.p.feedback.maxCorrection
  -- the torso's tilt on the ankles (not under a kick that names its support leg: it tilts the
  -- torso on purpose, Motion.kick)
  local tax, tay = 0, 0
  if not support then tax, tay = self:tilt_feedback(sensors, dt) end
  local thx, thy
  tax, tay, thx, thy = extension_feedback(self, support, tax, tay)
  local tx, ty = torso_estimate(self, sensors, sup, dt, lim)
  leg_feedback(self, q, sup, gx, gy, tax, tay, thx, thy, tx, ty, lim)
  if not support then extension_level(self, q, sensors, dt, ss > 0 and sup or nil) end
  arm_feedback(self, q, gx, gy, lim)
  return flags
end

-- The torso's tilt (IMU angle against the planned posture, low-passed) on the ankles, rad about the
-- torso's x and y axes: a foot that lands on an edge tips the stiff body with it; turning the ankle
-- by the tilt rights the leg over the foot (the foot's own ground, not the plan's). Config
-- feedback.tilt ({ roll, pitch }, rad per rad) and tiltTimeConstant (s); { 0, 0 }: off.
function Walk:tilt_feedback(sensors, dt)
  local fb, angle = self.p.feedback, sensors.angle
  local k = fb.tilt
  if not angle or (k[1] == 0 and k[2] == 0) then return 0, 0 end
  local tf = self.tilt_f or { 0, 0 }
  self.tilt_f = tf
  local a = clamp(dt / (dt + fb.tiltTimeConstant), 0, 1)
  tf[1] = tf[1] + a * (angle[1] - tf[1])
  -- the torso's pitch as planned: a kick out of the walk leans it on purpose (Motion.walk_kick)
  local pitch = self.p.bodyTilt + self:extra_pitch()
  tf[2] = tf[2] + a * (angle[2] - pitch - tf[2])
  return k[1] * tf[1], k[2] * tf[2]
end

-- Updates the COM offset (whole-body COM minus torso origin, in the heading frame) from joint
-- angles q through the mass model; filtered so that it follows the posture, not the noise.
function Walk:update_com_offset(q, alpha)
  local c = self.model:com(q, self.com_buf)
  self.com_buf = c
  local tp = self.p.bodyTilt
  local ox = c[1] * cos(tp) + c[3] * sin(tp)
  local o = self.com_offset
  alpha = alpha or 0.05
  o[1] = o[1] + alpha * (ox - o[1])
  o[2] = o[2] + alpha * (c[2] - o[2])
end

M.Walk = Walk
return M
