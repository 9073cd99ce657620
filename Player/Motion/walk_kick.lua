-- A kick out of the walk: on the next step whose swing foot is the kicking foot, that foot's swing
-- is replaced by a kick swing (lift, wind-up, a fast strike through the ball, retract, land where
-- the walk would have put it) while the support foot and the COM plan keep walking. A walk
-- extension of either engine (Player/Motion/walk.lua's stages `begin_step` at each step's start,
-- `swing` each tick, `pitch`, and `joints` after the leg IK): w:extend(require('Motion.walk_kick').new(p)).
--
-- Numbers from the walk config's `walkKick` (per body): `expire` (s a request waits at most),
-- `maxSpeed` = { vx, vy, va } (a kick waits for a step begun no faster), and per kind:
--   tStep, phSingle      the kick step's duration and single-support phase (longer than a step:
--                        the wind-up and strike need the time; the COM plan is made for it)
--   ball = { x, y }      m: where the ball's centre is taken to be when the request names none,
--                        ahead of the support ankle and outward of the kicking foot's line
--   ballMax              m (false: none): a ball (named by the request) further ahead of the support
--                        ankle than this at the kick step's start waits for the foot's next step
--                        (until `expire`)
--   contact = { x, y }   m: the kicking ankle's offset behind (x) and inward of (y) the ball's
--                        centre when the foot's striking face touches it
--   reach = { x = { lo, hi }, y = { lo, hi } }  m: the kicking ankle's box in the support foot's
--                        frame (y outward from the support ankle): every way-point is kept inside
--   support = { x, y }   m: the step's ZMP moved ahead of and outward from the support ankle
--   phases = { { duration = s, x, y (outward), z = m from the contact point (z above the ground),
--                hip, knee, ankle = rad (pitch added to the kicking leg after the IK, about the
--                torso's y axis: negative hip swings the leg forward), hipRoll = rad (about x,
--                outward positive), tilt = rad (the torso's pitch added, forward positive: thrown
--                back through the strike the leg swings faster in the world), arms = rad (both
--                arms back), arm = rad (the kicking side's arm back, the other forward) }, ... }
--                from the start of single support; after the last one the foot goes to its
--                landing point by the end of single support.
local walk = require('Motion.walk')

local floor = math.floor
local pose_global, pose_relative = walk.pose_global, walk.pose_relative

local M = {}
local Kick = {}
Kick.__index = Kick

M.KINDS = { forward = 1, side = 2 }
M.KIND_NAMES = { 'forward', 'side' }

local function clamp(x, lo, hi) if x < lo then return lo elseif x > hi then return hi end return x end
local function smooth(s) return s * s * (3 - 2 * s) end

-- params: the walk config (read live).
function M.new(params)
  return setmetatable({ p = params, pending = nil, cur = nil, count = 0, seq = 0, missed = 0,
    joint = { hip = 0, knee = 0, ankle = 0, hipRoll = 0, tilt = 0, arms = 0, arm = 0 }, tilt = 0 }, Kick)
end

-- Asks for a kick of `kind` ('forward' or 'side') with `foot` ('left' or 'right') on the next step
-- that swings that foot. ball: nil, or the ball's centre { x, y } in the walk's ground frame (as
-- odometry). Returns true, or nil and a message.
-- t: the robot's time (a request not honoured within walkKick.expire s is dropped: Kick:expire).
function Kick:request(kind, foot, ball, t)
  if not M.KINDS[kind] then return nil, "walk kick: kind must be 'forward' or 'side', got " .. tostring(kind) end
  if foot ~= 'left' and foot ~= 'right' then
    return nil, "walk kick: foot must be 'left' or 'right', got " .. tostring(foot)
  end
  local wk = self.p.walkKick
  if not wk then
    return nil, "walk kick: the walk config has no 'walkKick." .. kind .. "'"
  end
  self.pending = { kind = kind, foot = foot, ball = ball, t = t or 0 }
  self.seq = self.seq + 1
  return true
end

function Kick:cancel() self.pending = nil end

-- Drops a request older than walkKick.expire s at time t (the ball it was made for has moved on),
-- and any request while the walk does not step (active: the walk's is_active()).
function Kick:expire(t, active)
  local req = self.pending
  if req and (not active or t - req.t > self.p.walkKick.expire) then
    self.pending = nil
    self.expired = (self.expired or 0) + 1
  end
  if not active then self.cur, self.tilt = nil, 0 end
end

-- 0 none, 1 asked (waiting for a step that swings the kicking foot), 2 kicking
function Kick:phase()
  if self.cur then return 2 elseif self.pending then return 1 end
  return 0
end

-- The way-points of the kick swing in the support foot's frame ({ x, y, z }, y outward).
local function waypoints(cfg, sgn, ball_rel)
  local bx, by = ball_rel[1], sgn * ball_rel[2]
  local cx, cy = bx - cfg.contact.x, by - cfg.contact.y
  local rx, ry = cfg.reach.x, cfg.reach.y
  local pts = {}
  for i, ph in ipairs(cfg.phases) do
    pts[i] = { clamp(cx + ph.x, rx[1], rx[2]), clamp(cy + ph.y, ry[1], ry[2]), ph.z }
  end
  return pts
end

-- Stage `begin_step` (the step's targets are set: step.left, stance, start, target): a kick step
-- has its own duration, single-support phase and ZMP point (step.T, ph1, ph2, zmp).
function Kick:begin_step(w, step)
  if self.cur then self.cur = nil self.count = self.count + 1 end
  local req = self.pending
  if not req or w.stopping then return end
  local swing_left = step.left
  if (req.foot == 'left') ~= swing_left then return end
  local cfg = self.p.walkKick[req.kind]
  -- a kick step out of a faster walk throws the robot (the step's COM plan starts from the walk's
  -- speed): the request waits for a slower step (or expires)
  local v = w.vel
  if math.abs(v[1]) > self.p.walkKick.maxSpeed[1] or math.abs(v[2]) > self.p.walkKick.maxSpeed[2]
    or math.abs(v[3]) > self.p.walkKick.maxSpeed[3] then
    return
  end
  local sgn = swing_left and 1 or -1
  local sup = step.stance
  local ball = req.ball and pose_relative({ req.ball[1], req.ball[2], 0 }, sup)
    or { cfg.ball.x, sgn * (2 * self.p.footY + cfg.ball.y), 0 }
  -- a ball further ahead than the strike is made for waits for the next step of this foot, the
  -- walk bringing it nearer: beyond it the foot met the ball at the end of its reach, slowing down
  -- (forward kicks of the OP3: 1.2 m against 1.8 m a few centimetres nearer)
  local far = cfg.ballMax
  if far and req.ball and ball[1] > far then return end
  self.pending = nil
  -- the kick step lasts a whole number of ticks for an engine on a sample grid (walk_preview)
  local T = cfg.tStep
  if w.dt then T = floor(T / w.dt + 0.5) * w.dt end
  local ph1, ph2 = cfg.phSingle[1], cfg.phSingle[2]
  step.T, step.ph1, step.ph2 = T, ph1, ph2
  local s = cfg.support
  step.zmp = pose_global({ s.x + self.p.supportX, -sgn * (s.y + self.p.supportY), 0 }, sup)
  local start = step.start
  local a0 = pose_relative(start, sup)
  self.cur = { kind = req.kind, foot = req.foot, sgn = sgn, sup = sup, cfg = cfg, t1 = ph1 * T, t2 = ph2 * T,
    from = { a0[1], sgn * a0[2], 0 }, pts = waypoints(cfg, sgn, ball), ball = ball }
  local bx, by = ball[1] - cfg.contact.x, sgn * ball[2] - cfg.contact.y
  if bx < cfg.reach.x[1] or bx > cfg.reach.x[2] or by < cfg.reach.y[1] or by > cfg.reach.y[2] then
    self.missed = self.missed + 1 -- the ball's contact point is outside the foot's reach
  end
end

-- Stage `swing`, each tick of a step after the walk's own swing (t: time into the step): places
-- the kicking foot (step.foot, step.z) and sets the joint offsets while a kick swing runs.
function Kick:swing(_, step, t)
  local k, j = self.cur, self.joint
  for key in pairs(j) do j[key] = 0 end
  self.tilt = 0
  if not k then return end
  local phases = k.cfg.phases
  local tt = t - k.t1
  local x, y, z = k.from[1], k.from[2], k.from[3]
  if tt > 0 then
    local prev, pj = k.from, nil
    local i = 1
    while i <= #phases and tt > phases[i].duration do
      tt = tt - phases[i].duration
      prev, pj = k.pts[i], phases[i]
      i = i + 1
    end
    local to, tj, dur
    if i <= #phases then
      to, tj, dur = k.pts[i], phases[i], phases[i].duration
    else
      -- to the landing point by the end of single support
      local land = pose_relative(step.target, k.sup)
      to, tj = { land[1], k.sgn * land[2], 0 }, nil
      local used = 0
      for n = 1, #phases do used = used + phases[n].duration end
      dur = math.max(1e-3, k.t2 - k.t1 - used)
    end
    local s = smooth(clamp(tt / dur, 0, 1))
    x, y, z = prev[1] + s * (to[1] - prev[1]), prev[2] + s * (to[2] - prev[2]), prev[3] + s * (to[3] - prev[3])
    for key in pairs(j) do
      local a, b = pj and pj[key] or 0, tj and tj[key] or 0
      j[key] = a + s * (b - a)
    end
    self.tilt = j.tilt
  end
  local foot = step.foot
  local yaw = foot[3]
  local g = pose_global({ x, k.sgn * y, 0 }, k.sup)
  foot[1], foot[2], foot[3] = g[1], g[2], yaw
  step.z = z
end

-- Stage `pitch`: the torso's pitch the kick adds (rad, forward positive).
function Kick:pitch() return self.tilt end

-- Stage `joints`: the kick's joint offsets on the kicking leg (q: 1-based joint angles after the
-- leg IK).
function Kick:joints(w, q)
  local k = self.cur
  if not k then return end
  local j = self.joint
  local legi = w.legs[k.foot == 'left' and walk.LEFT or walk.RIGHT]
  local function rot(i, rx, ry) q[i] = q[i] + w.ax[i] * rx + w.ay[i] * ry end
  rot(legi[2], k.sgn * j.hipRoll, 0)
  rot(legi[3], 0, j.hip)
  rot(legi[4], 0, j.knee)
  rot(legi[5], 0, j.ankle)
  local karm, sarm = w.arms[k.foot == 'left' and 'l' or 'r'], w.arms[k.foot == 'left' and 'r' or 'l']
  if karm and karm.pitch then rot(karm.pitch, 0, j.arms + j.arm) end
  if sarm and sarm.pitch then rot(sarm.pitch, 0, j.arms - j.arm) end
end

return M
