-- Analytic linear inverted pendulum (LIPM) over one step with a piecewise-linear ZMP.
--
-- Along one horizontal axis, the centre of mass x obeys x'' = w^2 (x - p(t)), w = 1 / tZmp,
-- tZmp = sqrt(z_com / g). One step of duration T has a ZMP p(t) in three linear pieces:
--   [0, t1]   double support: p moves from a (the COM at the step's start) to s (support point)
--   [t1, t2]  single support: p stays at s
--   [t2, T]   double support: p moves from s to b (the COM at the step's end)
-- On each linear piece the particular solution is p itself; where p's slope changes by d at a knot
-- tk, the homogeneous part gains -d/w * sinh(w (t - tk)) so that x and x' stay continuous. With the
-- boundary conditions x(0) = a and x(T) = b one coefficient is left:
--   x(t) = p(t) + 2 A sinh(w t) - sum_k d_k / w * sinh(w (t - tk)) [t > tk]
-- No preview window: each step is solved on its own, from where the previous one ended.
local exp = math.exp

local M = {}

local function sinh(x) local e = exp(x) return 0.5 * (e - 1 / e) end
local function cosh(x) local e = exp(x) return 0.5 * (e + 1 / e) end
M.sinh, M.cosh = sinh, cosh

-- Solves one axis of one step. Returns a coefficient table (reused if `c` is given).
function M.solve(a, s, b, T, t1, t2, tZmp, c)
  c = c or {}
  local w = 1 / tZmp
  local m1 = t1 > 0 and (s - a) / t1 or 0
  local m3 = (T - t2) > 0 and (b - s) / (T - t2) or 0
  local d1, d2 = -m1, m3 -- slope changes at t1 and t2
  local A = (d1 * sinh(w * (T - t1)) + d2 * sinh(w * (T - t2))) / (2 * w * sinh(w * T))
  c.a, c.s, c.b, c.T, c.t1, c.t2, c.w = a, s, b, T, t1, t2, w
  c.m1, c.m3, c.d1, c.d2, c.A = m1, m3, d1, d2, A
  return c
end

-- ZMP p(t) of a solved step.
function M.zmp(c, t)
  if t < c.t1 then return c.a + c.m1 * t end
  if t <= c.t2 then return c.s end
  return c.s + c.m3 * (t - c.t2)
end

-- COM position and velocity at time t (0..T) of a solved step; also returns the ZMP.
function M.eval(c, t)
  local w = c.w
  local p, pd
  if t < c.t1 then p, pd = c.a + c.m1 * t, c.m1
  elseif t <= c.t2 then p, pd = c.s, 0
  else p, pd = c.s + c.m3 * (t - c.t2), c.m3 end
  local x = p + 2 * c.A * sinh(w * t)
  local xd = pd + 2 * c.A * w * cosh(w * t)
  if t > c.t1 then
    local u = w * (t - c.t1)
    x = x - c.d1 / w * sinh(u)
    xd = xd - c.d1 * cosh(u)
  end
  if t > c.t2 then
    local u = w * (t - c.t2)
    x = x - c.d2 / w * sinh(u)
    xd = xd - c.d2 * cosh(u)
  end
  return x, xd, p
end

return M
