-- Operational-space torque control of a limb (Khatib; the torque solve of Modules/wbc's priority.hpp,
-- wbc_torque.h) with the rest of the body held in position mode: the limb's joints are torque
-- driven, everything else (legs, torso, the other arm) is a stiff servo, so the limb's dynamics are
-- its block of the floating-base model (Lib/dynamics.lua) at the measured state.
--
--   local wt = require('wbc_torque')
--   local c = wt.new({ robot = 'hubo2plus', joints = { 'RSP', 'RSR', 'RSY', 'REB', 'RWY', 'RWP' },
--                      frame = 'r_palm' })
--   c:target({ x, y, z } [, { vx, vy, vz } [, { ax, ay, az }]])   -- the frame's position (velocity,
--                                      -- acceleration: feed-forward), in the base pose's world; nil: none
--   local tau = c:torques(q, qdot, base, gains, posture)           -- N m per limb joint, within limits
--   c:status()  --> { error = m, feasible = bool, sigma_min = ... }
--
-- The torques, with A the limb's mass matrix, J its frame's position Jacobian (limb columns), h its
-- Coriolis and gravity terms, N the dynamically consistent null space of the task:
--   tau = J^T Lambda (a_des + kp e + kd edot - Jdot qdot) + N^T A (kq (q0 - q) - dq qdot - damping qdot') + h
-- Without a target the task is gone (N = I): the limb gets its gravity and Coriolis terms, the
-- posture's pull and the joint damping only. gains: { kp (1/s^2), kd (1/s), posture_kp (1/s^2),
-- posture_kd (1/s), damping (1/s) }: the joint damping stays when the posture's gains are zero, and
-- acts on qdot' (qdot_damp: a smoother rate estimate of the caller's, else qdot).
-- Errors (an unknown joint or frame, a NaN in the state or a target) raise a Lua error naming it.
local ffi = require('ffi')
local native = require('native')
local dynamics = require('dynamics')
local Config = require('Config')

local format, error, tostring, type = string.format, error, tostring, type
local min, max, sqrt = math.min, math.max, math.sqrt

native.cdef('wbc', 'wbc_torque')   -- Modules/wbc/wbc_torque.h
local C = native.load('wbc')

local M = {}
local Ctl = {}
Ctl.__index = Ctl

local function finite(x) return type(x) == 'number' and x == x and x ~= math.huge and x ~= -math.huge end

-- opts: robot (name; nil: ROBOT), joints (names, the limb), frame (the task's frame).
function M.new(opts)
  local model = dynamics.load(opts.robot and { robot = opts.robot } or nil)
  local robot = Config.load('robot', nil, opts.robot and { robot = opts.robot } or nil)
  local actuators = Config.load('actuators')
  local index = {}
  for i, name in ipairs(model.joints) do index[name] = i end
  local cols, limit, friction = {}, {}, {}
  for k, name in ipairs(opts.joints) do
    local i = index[name] or error(format("wbc_torque: '%s' is no joint of %s", tostring(name), model.name), 2)
    cols[k] = 6 + i
    local a = actuators[robot.actuator[name] or robot.actuator[name:sub(2)]]
    limit[k] = a and a.torque or error(format("wbc_torque: joint '%s' has no actuator with a torque limit", name), 2)
    friction[k] = a.friction or 0
  end
  model:set({})
  model:pose(opts.frame)   -- an unknown frame is an error naming it, now
  local n = #opts.joints
  return setmetatable({
    model = model, joints = opts.joints, frame = opts.frame, n = n, cols = cols, limit = limit,
    friction = friction, dt = opts.dt,
    b_A = ffi.new('double[?]', n * n), b_J = ffi.new('double[?]', 3 * n), b_ref = ffi.new('double[3]'),
    b_tau0 = ffi.new('double[?]', n), b_tau = ffi.new('double[?]', n), b_rows = ffi.new('int[1]', 3),
    b_rep = ffi.new('wbc_torque_level[1]'), b_err = ffi.new('char[256]'),
    M = {}, J = {}, h = {}, v = {}, tau = {}, Jprev = nil, st = { error = 0, feasible = true, sigma_min = 0 },
  }, Ctl)
end

-- The task's target: position, velocity and acceleration (nil: 0) of the frame; nil: no task.
function Ctl:target(p, v, a)
  if p == nil then
    self.p_des = nil
    return
  end
  for _, x in ipairs({ { 'position', p }, { 'velocity', v }, { 'acceleration', a } }) do
    local what, t = x[1], x[2]
    if t ~= nil then
      if type(t) ~= 'table' or #t ~= 3 then
        error(format("wbc_torque: '%s' %s: 3 numbers expected", self.frame, what), 2)
      end
      for i = 1, 3 do
        if not finite(t[i]) then
          error(format("wbc_torque: '%s' %s[%d] is not a finite number (%s)", self.frame, what, i, tostring(t[i])), 2)
        end
      end
    end
  end
  self.p_des = { p[1], p[2], p[3] }
  self.v_des = v and { v[1], v[2], v[3] } or { 0, 0, 0 }
  self.a_des = a and { a[1], a[2], a[3] } or { 0, 0, 0 }
end

function Ctl:has_target() return self.p_des ~= nil end

-- The frame's position in the model's world (the state last given to torques).
function Ctl:position() return self.model:pose(self.frame, self.pose) end

function Ctl:status() return self.st end

-- The joint rates friction compensation goes by: J^+ v_des (J's damped right inverse) where the
-- target moves, else the measured qd; and whether the target moves.
function Ctl:friction_rates(qd)
  local n, J, out = self.n, self.b_J, self.fw or {}
  self.fw = out
  local v = self.p_des and self.v_des
  local moving = v and (v[1] * v[1] + v[2] * v[2] + v[3] * v[3]) > 1e-8
  if not moving then
    for k = 1, n do out[k] = qd[k] end
    return out, false
  end
  -- y = (J J^T + 1e-4 I)^-1 v, out = J^T y
  local G = {}
  for r = 1, 3 do
    G[r] = {}
    for c = 1, 3 do
      local s = r == c and 1e-4 or 0
      for k = 1, n do s = s + J[(r - 1) * n + k - 1] * J[(c - 1) * n + k - 1] end
      G[r][c] = s
    end
  end
  local a, b, c, d, e, f, g, h, i = G[1][1], G[1][2], G[1][3], G[2][1], G[2][2], G[2][3], G[3][1], G[3][2], G[3][3]
  local det = a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g)
  local inv = { { e * i - f * h, c * h - b * i, b * f - c * e }, { f * g - d * i, a * i - c * g, c * d - a * f },
    { d * h - e * g, b * g - a * h, a * e - b * d } }
  local y = {}
  for r = 1, 3 do y[r] = (inv[r][1] * v[1] + inv[r][2] * v[2] + inv[r][3] * v[3]) / det end
  for k = 1, n do
    out[k] = J[k - 1] * y[1] + J[n + k - 1] * y[2] + J[2 * n + k - 1] * y[3]
  end
  return out, true
end

-- The task's inverse inertia J A^-1 J^T (3 x 3 rows, m/s^2 per N) at the state last given to
-- torques: with the task's gain kp the arm's stiffness against a force on the frame is kp Lambda, so
-- a force f moves the frame by (1 / kp) J A^-1 J^T f. Second: A^-1 J^T (n x 3 rows): a torque t_k
-- on joint k (a gear's friction) moves the frame by (1 / kp) (A^-1 J^T)[k] t_k, so the gears'
-- friction can hold it up to (1 / kp) sum_k |(A^-1 J^T u)_k| friction_k from where the force alone
-- puts it along u.
function Ctl:compliance()
  local n, A, J = self.n, self.b_A, self.b_J
  -- X = A^-1 J^T by Gaussian elimination with partial pivoting on [A | J^T]
  local a = {}
  for r = 1, n do
    a[r] = {}
    for c = 1, n do a[r][c] = A[(r - 1) * n + c - 1] end
    for k = 1, 3 do a[r][n + k] = J[(k - 1) * n + r - 1] end
  end
  for col = 1, n do
    local piv = col
    for r = col + 1, n do if math.abs(a[r][col]) > math.abs(a[piv][col]) then piv = r end end
    a[col], a[piv] = a[piv], a[col]
    for r = 1, n do
      if r ~= col then
        local f = a[r][col] / a[col][col]
        for c = col, n + 3 do a[r][c] = a[r][c] - f * a[col][c] end
      end
    end
  end
  local out, x = {}, {}
  for r = 1, n do x[r] = { a[r][n + 1] / a[r][r], a[r][n + 2] / a[r][r], a[r][n + 3] / a[r][r] } end
  for i = 1, 3 do
    out[i] = {}
    for k = 1, 3 do
      local s = 0
      for r = 1, n do s = s + J[(i - 1) * n + r - 1] * x[r][k] end
      out[i][k] = s
    end
  end
  return out, x
end

-- Torques (N m, one per limb joint, within the actuators' limits) at the measured state: q, qdot
-- (every joint, robot order), base (the root link's pose, dynamics.lua's 6 numbers), gains (see the
-- header), posture (the limb's angles the null space pulls to; nil: none). Returns tau.
function Ctl:torques(q, qdot, base, gains, posture, qdot_damp)
  local m, n, cols = self.model, self.n, self.cols
  local v = self.v
  for c = 1, 6 do v[c] = 0 end
  for i = 1, m.n do
    local w = qdot[i]
    if not finite(w) or not finite(q[i]) then
      error(format("wbc_torque: joint '%s': the measured state is not finite", m.joints[i]), 2)
    end
    v[6 + i] = w
  end
  m:set(q, base, v)
  local Mf, Jf, h = m:mass_matrix(self.M), m:jacobian(self.frame, nil, self.J), m:nonlinear(self.h)
  local A, J = self.b_A, self.b_J
  for r = 1, n do
    for c = 1, n do A[(r - 1) * n + c - 1] = Mf[cols[r]][cols[c]] end
  end
  for r = 1, 3 do
    for c = 1, n do J[(r - 1) * n + c - 1] = Jf[r][cols[c]] end
  end
  local qd = {}
  for k = 1, n do qd[k] = qdot[cols[k] - 6] end
  -- the task's acceleration: feed-forward plus the PD on the frame's error, less Jdot qdot (the
  -- Jacobian's change over the last control period)
  local ntask = 0
  local st = self.st
  if self.p_des then
    local p = m:pose(self.frame, self.pose)
    self.pose = p
    local Jprev = self.Jprev
    local err2 = 0
    for r = 1, 3 do
      local xd, dJ = 0, 0
      for k = 1, n do
        local jk = J[(r - 1) * n + k - 1]
        xd = xd + jk * qd[k]
        if Jprev and self.dt then dJ = dJ + (jk - Jprev[(r - 1) * n + k]) / self.dt * qd[k] end
      end
      local e = self.p_des[r] - p[r]
      err2 = err2 + e * e
      self.b_ref[r - 1] = self.a_des[r] + gains.kp * e + gains.kd * (self.v_des[r] - xd) - dJ
    end
    st.error = sqrt(err2)
    ntask = 1
  else
    st.error = 0
  end
  self.Jprev = self.Jprev or {}
  for i = 1, 3 * n do self.Jprev[i] = J[i - 1] end
  -- the posture's torque and the joint damping, A (kq (q0 - q) - dq qdot - damping qdot'), in the task's
  -- null space: weighted by the mass matrix, so a light wrist gets a light torque (a damping in N m s/rad
  -- the arm's shoulder needs would make the wrist's 1e-3 kg m^2 unstable at the 200 Hz control rate)
  local acc = {}
  for k = 1, n do
    local e = posture and (posture[k] - q[cols[k] - 6]) or 0
    acc[k] = (gains.posture_kp or 0) * e - (gains.posture_kd or 0) * qd[k]
      - (gains.damping or 0) * (qdot_damp and qdot_damp[k] or qd[k])
  end
  local tau0 = self.b_tau0
  for r = 1, n do
    local s = 0
    for c = 1, n do s = s + A[(r - 1) * n + c - 1] * acc[c] end
    tau0[r - 1] = s
  end
  local tau = self.tau
  if ntask > 0 then
    if C.wbc_solve_torque(n, A, 1, self.b_rows, J, self.b_ref, tau0, self.b_tau, self.b_rep, self.b_err, 256) < 0 then
      error(ffi.string(self.b_err), 2)
    end
    st.feasible, st.sigma_min = self.b_rep[0].feasible == 1, self.b_rep[0].sigma_min
    for k = 1, n do tau[k] = self.b_tau[k - 1] end
  else
    st.feasible, st.sigma_min = true, 0
    for k = 1, n do tau[k] = tau0[k - 1] end
  end
  -- the gears' friction (the actuators' data) compensated in the direction the joint moves: a
  -- fraction gains.friction of it along the task's joint rates J^+ v_des while the target moves,
  -- else gains.friction_measured along the measured rate, within a band of gains.friction_band
  -- rad/s (smooth through zero). Without a target nothing is compensated: the friction helps hold.
  local fw, moving = self:friction_rates(qd)
  local fc = self.p_des and (moving and gains.friction or gains.friction_measured) or 0
  local band = gains.friction_band or 0.02
  for k = 1, n do
    local t = tau[k] + h[cols[k]] + fc * self.friction[k] * min(max(fw[k] / band, -1), 1)
    if not finite(t) then error(format("wbc_torque: joint '%s': the torque is not finite", self.joints[k]), 2) end
    tau[k] = min(max(t, -self.limit[k]), self.limit[k])
  end
  return tau
end

return M
