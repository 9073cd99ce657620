-- Ball filter: position and velocity of the ball in the robot frame (x forward, y left), a
-- constant-velocity Kalman filter with rolling resistance, moved by the walk's odometry between
-- sightings. Each axis keeps its own [p, v] covariance (the axes are treated as independent).
local M = {}

local Filter = {}
Filter.__index = Filter

-- cfg: process_noise (m/s^2), meas_noise (m, at 1 m; grows with range), deceleration (m/s^2),
-- friction (1/s), max_speed
function M.new(cfg)
  local f = setmetatable({ cfg = cfg }, Filter)
  f:reset()
  return f
end

function Filter:reset()
  self.x, self.y, self.vx, self.vy = 0, 0, 0, 0
  -- per axis covariance: { ppp, ppv, pvv }
  self.px = { 100, 0, 1 }
  self.py = { 100, 0, 1 }
  self.t_seen = -math.huge
  self.seen = false
  self.n_seen = 0
end

-- Moves the ball into the robot's new frame after the robot moved by (dx, dy, da), given in
-- the old robot frame (odometry between two updates).
function Filter:move_robot(dx, dy, da)
  local c, s = math.cos(-da), math.sin(-da)
  local px, py = self.x - dx, self.y - dy
  self.x, self.y = c * px - s * py, s * px + c * py
  self.vx, self.vy = c * self.vx - s * self.vy, s * self.vx + c * self.vy
end

local function predict_axis(P, dt, q)
  local a, b, d = P[1], P[2], P[3]
  -- F = [1 dt; 0 1]
  P[1] = a + 2 * dt * b + dt * dt * d + q * dt * dt * dt * dt / 4
  P[2] = b + dt * d + q * dt * dt * dt / 2
  P[3] = d + q * dt * dt
end

-- Advances the filter by dt seconds: the ball rolls and slows down, by rolling resistance (a
-- constant deceleration: a slow ball, as a dribbled one, stops within centimetres) and drag.
function Filter:predict(dt)
  if dt <= 0 then return end
  local cfg = self.cfg
  local sp = math.sqrt(self.vx * self.vx + self.vy * self.vy)
  local k = 0
  if sp > 1e-9 then k = math.max(0, sp - cfg.deceleration * dt) * math.exp(-cfg.friction * dt) / sp end
  -- the mean of the speeds at both ends of the step
  self.x = self.x + self.vx * dt * (1 + k) / 2
  self.y = self.y + self.vy * dt * (1 + k) / 2
  self.vx, self.vy = self.vx * k, self.vy * k
  local q = cfg.process_noise * cfg.process_noise
  predict_axis(self.px, dt, q)
  predict_axis(self.py, dt, q)
end

local function update_axis(P, z, p, v, r)
  local a, b, d = P[1], P[2], P[3]
  local s = a + r
  local k1, k2 = a / s, b / s
  local innov = z - p
  P[1] = (1 - k1) * a
  P[2] = (1 - k1) * b
  P[3] = d - k2 * b
  return p + k1 * innov, v + k2 * innov
end

-- A sighting at (x, y) in the robot frame at time t.
function Filter:observe(x, y, t)
  local cfg = self.cfg
  local range = math.sqrt(x * x + y * y)
  local sigma = cfg.meas_noise * math.max(0.3, range)
  local r = sigma * sigma
  local fresh = not self.seen or (t - self.t_seen) > cfg.reset_after
  local jump = (x - self.x) ^ 2 + (y - self.y) ^ 2 > (cfg.jump_distance + 0.3 * range) ^ 2
  if fresh or jump then
    self.x, self.y, self.vx, self.vy = x, y, 0, 0
    self.px = { r, 0, 1 }
    self.py = { r, 0, 1 }
  else
    self.x, self.vx = update_axis(self.px, x, self.x, self.vx, r)
    self.y, self.vy = update_axis(self.py, y, self.y, self.vy, r)
    local sp = math.sqrt(self.vx * self.vx + self.vy * self.vy)
    if sp > cfg.max_speed then
      self.vx, self.vy = self.vx * cfg.max_speed / sp, self.vy * cfg.max_speed / sp
    end
  end
  self.seen = true
  self.t_seen = t
  self.n_seen = self.n_seen + 1
end

-- Position uncertainty (m, 1 sigma, larger axis).
function Filter:sigma()
  return math.sqrt(math.max(self.px[1], self.py[1]))
end

return M
