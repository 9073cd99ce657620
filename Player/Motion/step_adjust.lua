-- Step adjustment (capture point) for either walk engine, a walk extension (Player/Motion/walk.lua).
--
-- The capture point's error e (heading frame, m: where the capture point is against where the walk
-- plans it) is estimated every tick from the IMU (Player/Motion/capture.lua). A push moves it;
-- the walk then catches itself with the next footstep, and with the step's timing where placement
-- alone comes too late:
--  * landing: the swing foot lands gain x (e beyond the dead band) x the activation (Motion.capture:
--    0 for normal walking's errors) further (at most `max`, within the step limits); while the foot
--    is still travelling its landing point moves (the swing goes on from where the foot is, no jump);
--  * which foot: a sideways error beyond `switchError` at a step's start makes the foot on the side
--    of the push the swing foot (support on the other), even twice in a row: stepping out with the
--    other foot would cross the legs;
--  * touch-down: a sideways error beyond `touchdownError` while the foot on the far side swings (it
--    cannot catch a push away from it) puts that foot down where it is within `touchdownTime`, and
--    the step ends there: the next step swings the foot on the side of the push at once.
--  * level landing: a pushed robot leans, and a foot that swings rigid with the leaning torso lands on
--    its edge and the robot stays tipped over it; the swing foot's ankle turns against the torso's
--    tilt (IMU) so that it lands flat (`level`, fraction of the tilt per axis), and the turn fades
--    out over `levelTime` once the foot carries (the leg then rights the torso over it).
-- All numbers in the walk config's `stepAdjust` (read live); gain 0: off.
-- A walk extension (Player/Motion/walk.lua's stages `support`, `begin_step`, `retarget`, `level`)
-- on the error of a capture estimate (Player/Motion/capture.lua):
--
--   local sa = require('Motion.step_adjust').new(cap)   -- cap: the capture extension (cap.err)
--   w:extend(sa)
local walk = require('Motion.walk')

local abs = math.abs

local M = {}
local StepAdjust = {}
StepAdjust.__index = StepAdjust

local function clamp(x, lo, hi) if x < lo then return lo elseif x > hi then return hi end return x end
local function beyond(v, d) if v > d then return v - d elseif v < -d then return v + d end return 0 end

-- Its state: nominal2 (the step's nominal landing: later ticks adjust from it, not from
-- themselves), retargeted (the landing moved this step), touchdown ({ t0, t_end, z0 } while the
-- swing foot is put down early), swing_level (per leg, the swing foot's levelling).
function M.new(capture) return setmetatable({ capture = capture }, StepAdjust) end

-- The step adjustment's config, or nil when it is off (or no error is estimated yet).
local function config(self, w)
  local sa = w.p.stepAdjust
  if sa.gain <= 0 or not (self.capture and self.capture.err) then return nil end
  return sa
end

-- The support foot for the step that begins (`support`: the alternation's choice): the foot away
-- from a large sideways error carries, so that the foot on the side of the push swings.
function StepAdjust:support(w, support)
  local sa = config(self, w)
  if not sa or support == nil then return support end
  local ey = self.capture.err[2]
  if abs(ey) < sa.switchError then return support end
  local want = ey > 0 and walk.RIGHT or walk.LEFT  -- pushed left (+y): the left foot swings
  if want ~= support then w.stats.switched = (w.stats.switched or 0) + 1 end
  return want
end

-- The landing of swing pose `target` from support pose `sup` (LEFT/RIGHT swing by `left`) moved
-- by the error, within the step limits; nil when the error is inside the dead band.
local function landing(self, w, sa, sup, target, left)
  local p, e, g = w.p, self.capture.err, self.capture.gate or { 1, 1 }
  -- (times the activation: Motion.capture)
  local ox = clamp(sa.gain * g[1] * beyond(e[1], sa.deadband[1]), -sa.max[1], sa.max[1])
  local oy = clamp(sa.gain * g[2] * beyond(e[2], sa.deadband[2]), -sa.max[2], sa.max[2])
  -- below 5 mm a landing stays nominal: a small steady bias of the estimate (an IMU's offset) must
  -- not keep the feet from ever coming together for a stop
  if abs(ox) < 0.005 then ox = 0 end
  if abs(oy) < 0.005 then oy = 0 end
  if ox == 0 and oy == 0 then return nil end
  local rel = walk.pose_relative(target, sup)
  -- the offset is in the heading frame; the support foot's frame is close enough to it
  local sgn = left and 1 or -1
  rel[1] = clamp(rel[1] + ox, p.stepLimitX[1], p.stepLimitX[2])
  rel[2] = sgn * clamp(sgn * (rel[2] + oy), p.stepLimitY[1], p.stepLimitY[2])
  return walk.pose_global(rel, sup)
end

-- The swing height during a touch-down: from where the foot was down to the ground.
local function touchdown_z(self, t)
  local td = self.touchdown
  local u = clamp((t - td.t0) / (td.t_end - td.t0), 0, 1)
  return td.z0 * (1 - u) * (1 - u)
end

-- At the start of a step (after the nominal landing is chosen): the landing moved by the error.
function StepAdjust:begin_step(w, step)
  self.touchdown, self.retargeted = nil, nil
  local left = step.left
  self.nominal2 = step.target
  local sa = config(self, w)
  if not sa then return end
  local sup = step.stance
  local adjusted = landing(self, w, sa, sup, self.nominal2, left)
  if not adjusted then return end
  step.target = adjusted
  w.stats.adjusted = (w.stats.adjusted or 0) + 1
end

-- Every tick of a step, before the feet are placed (t: the time into the step, s: the swing's
-- progress 0..1 on its way to the landing point). Moves the landing while the foot travels, or
-- starts a touch-down (the step ends at step.t_end) and lowers the foot.
function StepAdjust:retarget(w, step, t, s)
  if self.touchdown then step.z = touchdown_z(self, t) return end
  local sa = config(self, w)
  if not sa then return end
  local left = step.left
  local ey = self.capture.err[2]
  local ph = t / w.T
  local single = ph > w.ph1 and ph < w.ph2
  -- the swing foot is on the far side of the push: put it down where it is
  if single and abs(ey) > sa.touchdownError and (ey > 0) ~= left and w.T - t > sa.touchdownTime then
    local cur = step.foot
    local landed = { cur[1], cur[2], cur[3] }
    step.start, step.target = landed, landed
    self.touchdown = { t0 = t, t_end = t + sa.touchdownTime, z0 = step.z }
    step.t_end = self.touchdown.t_end
    step.z = touchdown_z(self, t)
    w.stats.touchdowns = (w.stats.touchdowns or 0) + 1
    return
  end
  -- the foot still travels: its landing point follows the error (from the nominal one), until
  -- `retarget` of its way (beyond it the foot would have to jump)
  if s < sa.retarget and self.nominal2 then
    local sup = step.stance
    local target = landing(self, w, sa, sup, self.nominal2, left) or self.nominal2
    local cur2 = step.target
    if abs(target[1] - cur2[1]) + abs(target[2] - cur2[2]) > 1e-4 then
      -- keep the foot where it is this tick: start' = (now - s target) / (1 - s)
      local now = step.foot
      local k = 1 / (1 - s)
      local start = { (now[1] - s * target[1]) * k, (now[2] - s * target[2]) * k, step.start[3] }
      step.start, step.target = start, target
      if not self.retargeted then w.stats.adjusted = (w.stats.adjusted or 0) + 1 end
      self.retargeted = true
    end
  end
end

-- The swing foot levelled against the torso's tilt (after the walk's feedback, into q): per leg a
-- correction (rad about the torso's x and y axes) that follows -tilt while the leg swings and
-- fades out while it carries. sup: the support leg in single support, nil otherwise.
function StepAdjust:level(w, q, sensors, dt, sup)
  local sa = config(self, w)
  local angle = sensors.angle
  if not sa or not angle then return end
  local p = w.p
  local lv = self.swing_level or { [walk.LEFT] = { 0, 0 }, [walk.RIGHT] = { 0, 0 } }
  self.swing_level = lv
  local roll, pitch = angle[1], angle[2] - p.bodyTilt
  local fade = clamp(dt / sa.levelTime, 0, 1)
  for side = walk.LEFT, walk.RIGHT do
    local c = lv[side]
    if sup ~= nil and side ~= sup then
      c[1], c[2] = -sa.level[1] * roll, -sa.level[2] * pitch
    else
      c[1], c[2] = c[1] * (1 - fade), c[2] * (1 - fade)
    end
    if c[1] ~= 0 or c[2] ~= 0 then
      local legi = w.legs[side]
      local ar, ap = legi[6], legi[5]
      q[ar] = q[ar] + w.ax[ar] * c[1] + w.ay[ar] * c[2]
      q[ap] = q[ap] + w.ax[ap] * c[1] + w.ay[ap] * c[2]
    end
  end
end

M.StepAdjust = StepAdjust
return M
