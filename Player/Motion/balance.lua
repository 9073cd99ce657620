-- Balance on the feet's force sensors, for any walk engine: the measured zero moment point (centre
-- of pressure of both feet, from dcm.sensor.ft or dcm.sensor.foot_pressure) against the engine's reference ZMP, fed
-- back into a shift of the centre of mass (the torso) in the ground plane: the DRC-HUBO walkers'
-- ZMP feedback to the pelvis offset (a foot's torque says where its ground reaction acts; moving the
-- COM against the error moves the ZMP back to the plan).
--
--   local balance = require('Motion.balance')
--   local b = balance.new(params, robot)   -- the walk config (read live); its `balance` table;
--                                          -- robot: the robot config (its foot_pressure, optional)
--   b:update(dt, ft, uLeft, uRight, zmp_ref, walking, press)  -- ft: 24 values (1-based,
--                                          -- dcm.sensor.ft's layout); press: dcm.sensor.foot_pressure
--                                          -- (1-based; read on a body with pressure sensors); feet
--                                          -- and reference in the engine's ground frame; walking:
--                                          -- true while stepping
--   balance.sole_cop(points, press, o)     -- one foot's point sensors: fz, x, y (below)
--   b.shift  -- { x, y }: add it to the COM (torso) position the engine plans, ground frame
--   b.zmp, b.err, b.contact -- the measured ZMP, its error, true when a foot carries weight
--   b:reset()
--   w:extend(b)  -- as a walk extension (Player/Motion/walk.lua's stage `shift_com`): each tick's
--                -- w:update_com_shift(sensors, dt) updates it from sensors.ft and the walk's feet
--                -- and planned ZMP, and sets the walk's COM shift
-- Config (the walk config's `balance`): zmpGain, walkGain ({ x, y }, 1/s), leakTime, maxShift (per
-- axis), maxRate (m/s), filterTime, walkFilterTime, minForce, sensorHeight; see the law below.
--
-- Per foot (6 values: fx fy fz mx my mz, the wrench the foot exerts on the leg about the sensor's
-- origin, foot frame; a foot flat on the ground): the centre of pressure relative to the point on
-- the sole below the sensor is ((-my - h fx) / fz, (mx - h fy) / fz), h the sensor's height above the
-- sole (boards that give fz, mx, my only read fx = fy = 0). A body with point pressure sensors
-- under its soles (robot.lua `foot_pressure`: each foot's sensors' {x, y} in its sole frame, the
-- foot frame of the walk) measures on them instead: a foot's fz is the sum of its sensors' forces
-- f_i and its centre of pressure their mean position weighted by them, sum(f_i p_i) / fz. Both
-- feet's, weighted by their fz, give the ZMP. A foot below `minForce` does not count; with no foot
-- on the ground (lifted, falling) the shift decays and nothing is measured.
--
-- The law, per axis: shift' = -k * err - shift / leakTime, |shift| <= maxShift, err the ZMP error
-- low-passed with filterTime (tf): an integral action, leaking so that an error it cannot remove
-- does not wind it up. Stability: the feet hold the COM where the joints put it, so the ZMP answers
-- a shift s as s - tZmp^2 s'' (the cart-table model) and, with the low-pass, the loop's
-- characteristic polynomial is (tf - k tZmp^2) s^2 + s + k: stable only while k < tf / tZmp^2. The
-- gain k is zmpGain capped at half that bound (the walk config's tZmp). It corrects what the plan
-- gets wrong slowly (a COM model error, a lean, a steady push), not a step's own ZMP swing: while
-- walking the swing from foot to foot is in the error at the gait's frequency, so walking has its
-- own gains and a longer low-pass (walkGain, walkFilterTime) that leave it out. Gains are per axis
-- { x, y } (the walk's ground frame): sideways the error of a walking robot is mostly the sway from
-- foot to foot, its measured ZMP held at the support foot's edge for part of each step.
-- The shift moves at most maxRate: a short push tips the robot onto its toes (the cart-table model
-- no longer holds: its foot turns), the error is large at once, and a fast shift back is itself a
-- push on the ZMP towards the toes (measured on the Hubo2+, the largest short push survived
-- standing, 275 N x 0.1 s with the feedback off: 94 N on without the limit, 256 N at 0.01 m/s,
-- 269 N at 0.004 m/s).
-- zmpGain = 0 switches it off (bodies with no F/T on their real hardware: their sim would have
-- them, the robot would not).
local cos, sin = math.cos, math.sin

local M = {}
local Balance = {}
Balance.__index = Balance

-- One foot's point pressure sensors: points { {x, y}, ... } in its sole frame, press their forces
-- (N, 1-based) from press[o + 1] on. Returns the foot's normal force and its centre of pressure
-- x, y in the sole frame (0, 0 with no force on it).
function M.sole_cop(points, press, o)
  local fz, sx, sy = 0, 0, 0
  for i, p in ipairs(points) do
    local f = press[o + i]
    fz, sx, sy = fz + f, sx + f * p[1], sy + f * p[2]
  end
  if fz > 0 then return fz, sx / fz, sy / fz end
  return fz, 0, 0
end

-- params: the walk config (its `balance` checked where it is loaded: Config/spec/walk.lua); robot:
-- the robot config (optional): its `foot_pressure`, when it has one, is what measure() reads.
function M.new(params, robot)
  local fp = robot and rawget(robot, 'foot_pressure') -- optional: a Config table errs on a missing key
  return setmetatable({ p = params, shift = { 0, 0 }, zmp = { 0, 0 }, err = { 0, 0 }, errf = { 0, 0 },
    cop = { { 0, 0 }, { 0, 0 } }, force = { 0, 0 }, contact = false,
    pressure = fp and { fp.lfoot.points, fp.rfoot.points } or nil }, Balance)
end

function Balance:reset()
  self.shift[1], self.shift[2] = 0, 0
  self.errf[1], self.errf[2] = 0, 0
  self.err[1], self.err[2] = 0, 0
  self.contact = false
end

local function clamp(x, lo, hi) if x < lo then return lo elseif x > hi then return hi end return x end

-- The ZMP of both feet in the ground frame from the sensors (ft 1-based: left foot 1-6, right 7-12;
-- on a body with pressure sensors press, 1-based: the left foot's, then the right's) and the feet's
-- poses {x, y, yaw}; into self.zmp. Returns true when a foot carries weight.
function Balance:measure(ft, uL, uR, press)
  local bp = self.p.balance
  local h, fmin = bp.sensorHeight, bp.minForce
  local sx, sy, sf = 0, 0, 0
  local pts = self.pressure
  for k, u in ipairs({ uL, uR }) do
    local fz, px, py
    if pts then
      fz, px, py = M.sole_cop(pts[k], press, k == 1 and 0 or #pts[1])
    else
      local o = 6 * (k - 1)
      local fx, fy, mx, my = ft[o + 1], ft[o + 2], ft[o + 4], ft[o + 5]
      fz = ft[o + 3]
      if fz > fmin then px, py = (-my - h * fx) / fz, (mx - h * fy) / fz end
    end
    self.force[k] = fz
    if fz > fmin then
      self.cop[k][1], self.cop[k][2] = px, py
      local c, s = cos(u[3]), sin(u[3])
      sx = sx + fz * (u[1] + c * px - s * py)
      sy = sy + fz * (u[2] + s * px + c * py)
      sf = sf + fz
    end
  end
  if sf <= 0 then return false end
  self.zmp[1], self.zmp[2] = sx / sf, sy / sf
  return true
end

-- One tick: measure, filter the error against zmp_ref {x, y}, integrate the shift.
function Balance:update(dt, ft, uL, uR, zmp_ref, walking, press)
  local bp = self.p.balance
  local shift = self.shift
  local decay = clamp(dt / bp.leakTime, 0, 1)
  self.contact = self:measure(ft, uL, uR, press)
  local tf = walking and bp.walkFilterTime or bp.filterTime
  local cap = 0.5 * tf / (self.p.tZmp * self.p.tZmp)
  local g = walking and bp.walkGain or bp.zmpGain
  local gx, gy = clamp(g[1], 0, cap), clamp(g[2], 0, cap)
  local err, ef = self.err, self.errf
  if self.contact then
    -- measured with the feedback off too (its figures)
    err[1], err[2] = self.zmp[1] - zmp_ref[1], self.zmp[2] - zmp_ref[2]
    local alpha = clamp(dt / (dt + tf), 0, 1)
    ef[1] = ef[1] + alpha * (err[1] - ef[1])
    ef[2] = ef[2] + alpha * (err[2] - ef[2])
  end
  if not self.contact then gx, gy = 0, 0 end
  -- the rate limit on the net change (integral and leak together: a leak faster than the limit
  -- would hold the shift at maxRate * leakTime)
  local lim, step = bp.maxShift, bp.maxRate * dt
  local x, y = shift[1], shift[2]
  shift[1] = clamp(x + clamp(-x * decay - gx * ef[1] * dt, -step, step), -lim, lim)
  shift[2] = clamp(y + clamp(-y * decay - gy * ef[2] * dt, -step, step), -lim, lim)
  return shift
end

-- Stage `shift_com` of walk w: one update from the feet's sensors (sensors.ft, sensors.press)
-- against the ZMP the walk planned for the tick just done; the shift into `shift`.
function Balance:shift_com(w, sensors, dt, shift)
  local s = self:update(dt, sensors.ft, w.uLeft, w.uRight, w.zmp, w:is_active(), sensors.press)
  shift[1], shift[2] = s[1], s[2]
end

M.Balance = Balance
return M
