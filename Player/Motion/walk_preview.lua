-- The second walk engine: the same footsteps, swing and IK as Motion.walk, with the centre of mass
-- from ZMP preview control (Motion.preview) instead of the per-step analytic pendulum.
--
-- At the start of every step the engine lays out the ZMP reference on its sample grid (one sample
-- per motion tick) for the whole preview window: the step that begins and the steps that would follow
-- at the commanded velocity (the same footstep rules, rate limits and support alternation as the walk
-- itself), each step's ZMP in the analytic engine's three linear pieces. Every tick one preview
-- controller per axis advances the COM. Across step boundaries the COM's velocity and acceleration stay
-- continuous (the analytic engine fixes both ends of every step instead), and a change of command is
-- anticipated a window ahead. Steps last a whole number of ticks so that a sample's reference never
-- depends on float rounding (see Motion.preview).
-- Chosen per robot by the walk config's `engine = 'preview'`; weights in its `preview` table.
local walk = require('Motion.walk')
local preview = require('Motion.preview')

local abs, floor, max = math.abs, math.floor, math.max
local LEFT = walk.LEFT
local function copy3(dst, src) dst[1], dst[2], dst[3] = src[1], src[2], src[3] return dst end
local pose_global, pose_relative, interp = walk.pose_global, walk.pose_relative, walk.interp

local M = {}
local Preview = setmetatable({}, { __index = walk.Walk })
Preview.__index = Preview

local G = 9.81

-- params: the walk config (read live); model: Lib/kinematics model; dt: the motion tick (also taken
-- from robot.period by bind()).
function M.new(params, model, dt)
  local w = walk.new(params, model)
  setmetatable(w, Preview)
  w.dt = dt
  w.k = 0            -- sample index of the next tick
  w.ring = { {}, {} } -- ZMP reference (x, y) by sample index modulo the ring's size
  w.ring_size = 0
  w.ctl = nil
  w.lead = 0          -- ticks of lead-in left before the first step
  w.settle = 0        -- ticks left for the COM to come to rest after the last step
  return w
end

function Preview:bind(robot, files)
  walk.Walk.bind(self, robot, files)
  self.dt = robot.period
  return self
end

-- Samples per step at velocity v (default: the walk's): the step's period rounded to whole ticks.
function Preview:step_samples(v)
  assert(self.dt, 'walk_preview: the motion tick is unknown (bind() the walk to the robot)')
  return max(1, floor(walk.step_period(self.p, v or self.vel) / self.dt + 0.5))
end

function Preview:step_time(v) return self:step_samples(v) * self.dt end

-- the ZMP reference from sample k0 to k1 at c (x, y)
local function fill_const(self, k0, k1, c)
  local rx, ry, size = self.ring[1], self.ring[2], self.ring_size
  for k = k0, k1 do local i = k % size rx[i], ry[i] = c[1], c[2] end
end

-- A walk starts with a lead-in in double support: the first step is planned at once, to begin
-- `preview.lead` s later, so that the COM can move before the ZMP must (without it, the first
-- ticks ask for a ZMP far outside the feet).
function Preview:start()
  local was_active = self.active
  walk.Walk.start(self)
  if not was_active then
    self.ctl = nil -- from rest at the stance COM
    self.lead = max(0, floor(self.p.preview.lead / self.dt + 0.5))
    self.lead_planned = false
  end
end

-- After the last step the COM comes to rest under the controller (the reference holds the feet's
-- middle) for `preview.lead` s before it is simply held there: no jump into stance. The window
-- reaches past what the last step planned while it settles: each tick writes the window's last
-- sample with the middle (the ring's older samples there belong to steps long past).
function Preview:begin_step()
  local stepping = walk.Walk.begin_step(self)
  if not stepping and self.ctl then
    self.settle = max(0, floor(self.p.preview.lead / self.dt + 0.5))
    self.rest = { self.uTorso2[1], self.uTorso2[2] }
  end
  return stepping
end

function Preview:hold_com(x, y, dt)
  if self.settle > 0 and self.ctl and dt and dt > 0 then
    self.settle = self.settle - 1
    local last = self.k - 1 + self.K.N
    fill_const(self, last, last, self.rest)
    local cx, cxd, zx, cy, cyd, zy = self:com_at()
    self.com[1], self.com[2], self.comd[1], self.comd[2] = cx, cy, cxd, cyd
    self.zmp[1], self.zmp[2] = zx, zy
    if self.settle == 0 then self.ctl = nil end
    return
  end
  if self.settle == 0 then return walk.Walk.hold_com(self, x, y) end
end

function Preview:advance(dt)
  if not (self.active and self.lead > 0) then return walk.Walk.advance(self, dt) end
  if not self.lead_planned then
    self.lead_planned = true
    self.first_k = self.k + self.lead
    if not self:begin_step() then self.lead = 0 return walk.Walk.advance(self, dt) end
  end
  self.lead = self.lead - 1
  if self.lead == 0 then self.t = -dt end -- the next tick is the first step's first (t = 0)
  -- the feet stay where they stand; the COM moves under the controller
  copy3(self.uLeft, self.uLeft1)
  copy3(self.uRight, self.uRight1)
  local x, xd, zx, y, yd, zy = self:com_at()
  self.com[1], self.com[2], self.comd[1], self.comd[2] = x, y, xd, yd
  self.zmp[1], self.zmp[2] = zx, zy
  self.uTorso[1], self.uTorso[2] = x, y
  self.ph, self.swing_z = 0, 0
  self:place_feet()
  return true
end

function Preview:reset(u)
  walk.Walk.reset(self, u)
  self.ctl = nil
end

-- The gains for the current tick, tZmp and weights; recomputed when one of them changes (live).
function Preview:gains()
  local p, dt = self.p, self.dt
  local q = p.preview
  local N = max(1, floor(q.window / dt + 0.5))
  local key = string.format('%.9g %.9g %.9g %.9g %d', dt, p.tZmp, q.Qe, q.R, N)
  if key ~= self.gains_key then
    self.sys = preview.model(dt, p.tZmp * p.tZmp * G, G)
    self.K = preview.gains(self.sys, q.Qe, q.R, N)
    self.gains_key = key
    if self.ctl then for _, c in ipairs(self.ctl) do c:set_gains(self.sys, self.K) end end
  end
  return self.K
end

-- ZMP reference of one step into the ring: from `a` (COM target at its start) over support point `s`
-- to `b`, samples k0 .. k0 + n - 1, in the analytic engine's three pieces.
local function fill_step(self, k0, n, a, s, b, ph1, ph2)
  local n1 = floor(ph1 * n + 0.5)
  local n2 = floor(ph2 * n + 0.5)
  local rx, ry, size = self.ring[1], self.ring[2], self.ring_size
  for j = 0, n - 1 do
    local u
    if j < n1 then u = j / n1
    elseif j <= n2 then u = 1
    else u = 1 + (j - n2) / (n - n2) end
    local x, y
    if u <= 1 then x, y = a[1] + u * (s[1] - a[1]), a[2] + u * (s[2] - a[2])
    else u = u - 1 x, y = s[1] + u * (b[1] - s[1]), s[2] + u * (b[2] - s[2]) end
    local i = (k0 + j) % size
    rx[i], ry[i] = x, y
  end
end

local function feet_together(p, l, r)
  local rel = pose_relative(l, r)
  return abs(rel[1]) < 1e-3 and abs(rel[2] - 2 * p.footY) < 1e-3 and abs(rel[3]) < 1e-3
end

-- The steps that follow the one under way (from sample k on, to the window's end) at the commanded
-- velocity, as begin_step() will take them. Called at each step's start, and again when the command
-- changes or a stop is asked mid-step: a change seen a step earlier is a change the COM can prepare
-- for (replanned only at the next step, a stop gave a 3 cm ZMP spike ahead of the feet).
local function plan_ahead(self, k)
  local p = self.p
  local last = self.next_k + self.K.N
  local v = { self.vel[1], self.vel[2], self.vel[3] }
  local l, r, torso, support = self.uLeft2, self.uRight2, self.uTorso2, self.support
  local still_steps = self.steps_still or 0
  local sY = p.supportY
  while k <= last do
    self:update_velocity(v, self.stopping)
    -- the stop rule of begin_step()
    local still = abs(v[1]) < 1e-4 and abs(v[2]) < 1e-4 and abs(v[3]) < 1e-4
    if self.stopping and still and feet_together(p, l, r) and still_steps >= 1 then break end
    still_steps = still and still_steps + 1 or 0
    support = 1 - support
    local ve = { v[1], v[2], v[3] + self.va_correction }
    local n = self:step_samples(ve)
    local s
    if support == LEFT then
      r = self:step_target(l, false, ve)
      s = pose_global({ p.supportX, sY, 0 }, l)
    else
      l = self:step_target(r, true, ve)
      s = pose_global({ p.supportX, -sY, 0 }, r)
    end
    local b = pose_global({ p.supportX, 0, 0 }, interp(0.5, l, r))
    fill_step(self, k, n, torso, s, b, p.phSingle[1], p.phSingle[2])
    torso, k = b, k + n
  end
  if k <= last then fill_const(self, k, last, torso) end
end

-- Called by begin_step(): this step's ZMP and the planned steps' over the preview window.
function Preview:plan_com()
  local K = self:gains()
  -- this step's samples (an extension may have made it longer than tStep: Motion.walk_kick)
  local n = max(1, floor(self.T / self.dt + 0.5))
  local N = K.N
  -- the step begins at the next tick's sample, or after the lead-in of a walk that starts
  local k0 = self.first_k or self.k
  self.first_k = nil
  -- the ring holds from this tick's sample to the window's end past the step
  local size = (k0 - self.k) + N + 2 * n + 4
  if size > self.ring_size then self.ring = { {}, {} } self.ring_size = size end
  if not self.ctl then
    -- at rest over the stance COM
    local ctl = { preview.controller(self.sys, K, self.com[1]), preview.controller(self.sys, K, self.com[2]) }
    self.ctl = ctl
  end
  fill_const(self, self.k - 1, k0 - 1, self.uTorso1)
  -- this step with the phases it latched; the planned ones with today's (they latch them in turn)
  fill_step(self, k0, n, self.uTorso1, self.uSupport, self.uTorso2, self.ph1, self.ph2)
  self.next_k = k0 + n
  plan_ahead(self, self.next_k)
end

-- A new command or a stop mid-step: the steps after this one are planned again at once.
function Preview:set_velocity(vx, vy, va)
  local c = self.cmd
  local ox, oy, oa = c[1], c[2], c[3]
  local x, y, a = walk.Walk.set_velocity(self, vx, vy, va)
  if x and (x ~= ox or y ~= oy or a ~= oa) and self.active and self.ctl and self.next_k then
    plan_ahead(self, self.next_k)
  end
  return x, y, a
end

function Preview:stop()
  local was_stopping = self.stopping
  walk.Walk.stop(self)
  if self.stopping and not was_stopping and self.ctl and self.next_k then plan_ahead(self, self.next_k) end
end

-- One tick of the preview controllers; the COM at the tick's sample.
function Preview:com_at()
  local k, size = self.k, self.ring_size
  local rx, ry = self.ring[1], self.ring[2]
  local x, xd, _, zx = self.ctl[1]:step_ring(rx, k - 1, size)
  local y, yd, _, zy = self.ctl[2]:step_ring(ry, k - 1, size)
  self.k = k + 1
  return x, xd, zx, y, yd, zy
end

M.Preview = Preview
return M
