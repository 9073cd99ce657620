-- ZMP preview control on the cart-table model (Kajita et al. 2003, with Katayama's integral action).
--
-- One horizontal axis. The state is x = [c, c', c''] (COM position, velocity, acceleration), the input
-- the COM jerk u, sampled every dt:
--   x(k+1) = A x(k) + B u(k),   p(k) = C x(k) = c - zc/g c''   (the ZMP of a cart on a table)
-- The controller minimises sum Qe (p - p_ref)^2 + R u^2 over an infinite horizon while it knows the
-- reference N samples ahead:
--   u(k) = -Gi sum_{i<=k} (p(i) - p_ref(i)) - Gx x(k) - sum_{j=1..N} Gd(j) p_ref(k+j)
-- Gi and Gx come from the discrete algebraic Riccati equation of the system augmented with the
-- integrated ZMP error; the preview gains Gd(j) from the closed loop. The input is a scalar, so every
-- inverse is a division. Gains are computed once per (dt, zc, Qe, R, N) at load; a tick costs N
-- multiply-adds per axis.
local M = {}

-- 4x4 and 4-vector helpers over 1-based Lua arrays (row-major: m[r][c]).
local function mat(n) local m = {} for r = 1, n do m[r] = {} for c = 1, n do m[r][c] = 0 end end return m end
local function mul(a, b)
  local n, m = #a, mat(#a)
  for r = 1, n do for c = 1, n do
    local s = 0
    for k = 1, n do s = s + a[r][k] * b[k][c] end
    m[r][c] = s
  end end
  return m
end
local function transpose(a)
  local n, m = #a, mat(#a)
  for r = 1, n do for c = 1, n do m[c][r] = a[r][c] end end
  return m
end
local function mulv(a, v) -- a v
  local out = {}
  for r = 1, #a do local s = 0 for k = 1, #v do s = s + a[r][k] * v[k] end out[r] = s end
  return out
end
local function dot(u, v) local s = 0 for i = 1, #u do s = s + u[i] * v[i] end return s end

-- The discrete cart-table model for a sample time dt and COM height zc (g in m/s^2).
function M.model(dt, zc, g)
  g = g or 9.81
  return {
    A = { { 1, dt, dt * dt / 2 }, { 0, 1, dt }, { 0, 0, 1 } },
    B = { dt * dt * dt / 6, dt * dt / 2, dt },
    C = { 1, 0, -zc / g },
  }
end

-- Gains for model `sys` (M.model), weights Qe (ZMP error) and R (jerk), preview length N samples.
-- Returns { Gi = number, Gx = {3}, Gd = {N}, P = 4x4, iterations = n }.
function M.gains(sys, Qe, R, N)
  assert(Qe > 0 and R > 0 and N >= 1, 'preview.gains: Qe and R must be > 0 and N >= 1')
  local A, B, C = sys.A, sys.B, sys.C
  -- Augmented system: state [sum of ZMP error increments; x increment] (Katayama's form).
  local CA = { 0, 0, 0 }
  for c = 1, 3 do for k = 1, 3 do CA[c] = CA[c] + C[k] * A[k][c] end end
  local At = mat(4)
  At[1][1] = 1
  for c = 1, 3 do At[1][c + 1] = CA[c] end
  for r = 1, 3 do for c = 1, 3 do At[r + 1][c + 1] = A[r][c] end end
  local Bt = { dot(C, B), B[1], B[2], B[3] }
  local AtT = transpose(At)
  -- Riccati iteration P <- At' P At - At' P Bt (R + Bt' P Bt)^-1 Bt' P At + Q, Q = Qe e1 e1'.
  local P = mat(4)
  P[1][1] = Qe
  local iterations, converged = 0, false
  for it = 1, 200000 do
    local PA = mul(P, At)
    local PB = mulv(P, Bt)
    local s = R + dot(Bt, PB)
    local BPA = {} -- Bt' P At (row)
    for c = 1, 4 do local v = 0 for k = 1, 4 do v = v + Bt[k] * PA[k][c] end BPA[c] = v end
    local Pn = mul(AtT, PA)
    local delta, scale = 0, 0
    for r = 1, 4 do for c = 1, 4 do
      Pn[r][c] = Pn[r][c] - BPA[r] * BPA[c] / s + ((r == 1 and c == 1) and Qe or 0)
      delta = math.max(delta, math.abs(Pn[r][c] - P[r][c]))
      scale = math.max(scale, math.abs(Pn[r][c]))
    end end
    P = Pn
    iterations = it
    if delta <= 1e-12 * scale then converged = true break end
  end
  assert(converged, 'preview.gains: the Riccati iteration did not converge (check dt, zc, Qe, R)')
  local PB = mulv(P, Bt)
  local s = R + dot(Bt, PB)
  local PA = mul(P, At)
  local K = {}
  for c = 1, 4 do local v = 0 for k = 1, 4 do v = v + Bt[k] * PA[k][c] end K[c] = v / s end
  -- Closed loop Ac = At - Bt K; X(1) = -Ac' P I1; Gd(1) = -Gi; Gd(j) = Bt' X(j-1) / s; X(j) = Ac' X(j-1).
  local Ac = mat(4)
  for r = 1, 4 do for c = 1, 4 do Ac[r][c] = At[r][c] - Bt[r] * K[c] end end
  local AcT = transpose(Ac)
  local X = mulv(AcT, { -P[1][1], -P[2][1], -P[3][1], -P[4][1] })
  local Gd = { -K[1] }
  for j = 2, N do
    Gd[j] = dot(Bt, X) / s
    X = mulv(AcT, X)
  end
  return { Gi = K[1], Gx = { K[2], K[3], K[4] }, Gd = Gd, P = P, iterations = iterations, N = N }
end

-- A controller for one axis: holds the state and the integrated ZMP error.
-- ctl = M.controller(sys, gains, c0); ctl:step(ref) with ref(j) the ZMP reference j samples ahead
-- (j = 0..N; ref(0) is this sample's, ref(1) the next one's). Returns c, c', c'' and the ZMP after
-- the step. ref(j) must give the same value for the same sample on every tick: build it on sample
-- indices, not float times, or a sample that falls on either side of a step from tick to tick is
-- amplified by the preview gains (~2 cm of ZMP error on a 4 cm step).
local Controller = {}
Controller.__index = Controller

function M.controller(sys, gains, c0)
  return setmetatable({ sys = sys, k = gains, x = { c0 or 0, 0, 0 }, esum = 0 }, Controller)
end

function Controller:zmp() return dot(self.sys.C, self.x) end

function Controller:reset(c, cd, cdd)
  self.x[1], self.x[2], self.x[3], self.esum = c or 0, cd or 0, cdd or 0, 0
end

local function advance(self, u)
  local sys, x = self.sys, self.x
  local A, B = sys.A, sys.B
  local x1 = A[1][1] * x[1] + A[1][2] * x[2] + A[1][3] * x[3] + B[1] * u
  local x2 = A[2][2] * x[2] + A[2][3] * x[3] + B[2] * u
  local x3 = x[3] + B[3] * u
  x[1], x[2], x[3] = x1, x2, x3
  return x1, x2, x3, dot(sys.C, x)
end

function Controller:step(ref)
  local k, x = self.k, self.x
  self.esum = self.esum + (dot(self.sys.C, x) - ref(0))
  local u = -k.Gi * self.esum - dot(k.Gx, x)
  local Gd = k.Gd
  for j = 1, k.N do u = u - Gd[j] * ref(j) end
  return advance(self, u)
end

-- The same with the reference in a ring buffer: ref(j) = buf[(k0 + j) % size] (no closure per tick).
function Controller:step_ring(buf, k0, size)
  local k, x = self.k, self.x
  self.esum = self.esum + (dot(self.sys.C, x) - buf[k0 % size])
  local u = -k.Gi * self.esum - dot(k.Gx, x)
  local Gd = k.Gd
  for j = 1, k.N do u = u - Gd[j] * buf[(k0 + j) % size] end
  return advance(self, u)
end

-- New gains (a parameter changed live): the state and the integrated error carry over.
function Controller:set_gains(sys, gains) self.sys, self.k = sys, gains end

return M
