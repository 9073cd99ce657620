-- The world model: ball (robot frame) and the robot's pose on the field, from the vision block's
-- detections and the walk's odometry (motion block); written to the world block.
--
--   local world = require('World.world').new(cfg)     -- cfg = Config behavior.lua's `world` part
--   world:update(t, odometry, vision)                 -- once per behavior step
--   world.ball.x ... ; world:ball_field(); world:goal_in_robot_frame()
--   world.obstacles: other robots seen lately, robot frame: { { x, y, team (-1, 0 blue, 1 red), t }, ... }
local ball_filter = require('World.ball_filter')
local pose_filter = require('World.pose_filter')

local M = {}

local cos, sin, atan2, sqrt = math.cos, math.sin, math.atan2, math.sqrt
local wrap = pose_filter.wrap
local PARTICLES_SHOWN = 100  -- the world block's `particles` holds 100 x, y, yaw (Config/shm.schema)

local World = {}
World.__index = World

-- A small deterministic generator (xorshift) so that runs with the same seed agree.
local function make_rng(seed)
  local state = bit.tobit(seed * 2654435761 % 4294967296)
  if state == 0 then state = 1 end
  return function()
    state = bit.bxor(state, bit.lshift(state, 13))
    state = bit.bxor(state, bit.rshift(state, 17))
    state = bit.bxor(state, bit.lshift(state, 5))
    return (state % 4294967296) / 4294967296
  end
end
M.make_rng = make_rng

-- cfg: { field = {...}, ball = {...}, pose = {...}, seed = n }
function M.new(cfg)
  local w = setmetatable({ cfg = cfg }, World)
  w.ball = ball_filter.new(cfg.ball)
  w.pose = pose_filter.new(cfg.field, cfg.pose, make_rng(cfg.seed or 1))
  w.t = nil
  w.odom = nil
  w.frame = nil
  w.odometry_jumps = 0
  w.obstacles = {}
  return w
end

-- Back to the prior (anywhere in the own half, any heading): the robot may have been carried
-- while the game was in its initial state (placed by hand, or by a scenario), and a belief formed
-- before that would be confident and wrong (the two goals look alike, so no later sighting
-- contradicts a mirrored belief).
-- after_penalty: put back by a referee (on either touch line); first_half: the GameController's
-- (the placement config names the touch line of the first half; the sides change at half time).
function World:reset_pose(after_penalty, first_half)
  self.pose:init_prior(self:placement_lines(after_penalty, first_half))
  self.pose.fit = nil
end

-- The touch lines (their y sign, team frame) the robot is placed on, facing into the field, by the
-- pose config's `placement`: 'anywhere' (nil: anywhere in the own half, any heading), 'touchline'
-- (either), 'left'/'right' (y > 0 / y < 0 seen from the own goal, in the first half; the other in
-- the second). A robot put back after a penalty: either touch line.
function World:placement_lines(after_penalty, first_half)
  local pl = self.cfg.pose.placement
  if pl == 'anywhere' then return nil end
  if after_penalty or pl == 'touchline' then return { -1, 1 } end
  local s = pl == 'left' and 1 or -1
  if first_half == false then s = -s end
  return { s }
end

-- Continues from a belief this process's predecessor published (the world block): a restarted
-- behavior process on a robot nobody carried. The particles start around the published pose,
-- spread by `spread` (m, rad); the next sightings sharpen it.
function World:resume(x, y, a, spread)
  self.pose:set_pose(x, y, a, spread)
end

-- Odometry delta (dx, dy in the old robot frame, da) between two odometry readings {x, y, a}.
local function odom_delta(o0, o1)
  local ddx, ddy = o1[1] - o0[1], o1[2] - o0[2]
  local c, s = cos(-o0[3]), sin(-o0[3])
  return c * ddx - s * ddy, s * ddx + c * ddy, wrap(o1[3] - o0[3])
end
M.odom_delta = odom_delta

-- One step at robot time t. odometry = {x, y, yaw} (cumulative, from the motion block);
-- vision = { frame, time, ball_detected, ball = {x, y}, posts = {{x, y}, ...} } or nil.
-- imu_yaw (optional): the IMU's yaw (rad); only its changes are used, as the turn between steps
-- in place of the walk's (the walk reports the turn it planned, not how the body actually turned
-- when a foot slips or pushes the ball).
-- view (optional): { pan = the head's pan (rad), half_fov = the camera's half horizontal field of
-- view (rad) }: what the camera can see now, so that an obstacle outside it is not forgotten for
-- not being seen (forget_obstacles).
function World:update(t, odometry, vision, imu_yaw, view)
  local dt = self.t and (t - self.t) or 0
  self.t = t
  local imu_da
  if imu_yaw and self.imu_yaw then
    imu_da = wrap(imu_yaw - self.imu_yaw)
    if math.abs(imu_da) > 0.5 then imu_da = nil end -- a glitch (or lying on the ground): not a turn
  end
  self.imu_yaw = imu_yaw
  if imu_yaw then self.pose:imu(imu_yaw) end
  if self.odom then
    local dx, dy, da = odom_delta(self.odom, odometry)
    if imu_da and math.abs(da) <= 1.0 then da = imu_da end
    if dx * dx + dy * dy > self.cfg.max_odometry_step ^ 2 or math.abs(da) > 1.0 then
      -- the motion process restarted (its odometry began again): skip this step
      self.odometry_jumps = self.odometry_jumps + 1
    elseif dx ~= 0 or dy ~= 0 or da ~= 0 then
      self.ball:move_robot(dx, dy, da)
      self.pose:move(dx, dy, da)
      self:move_obstacles(dx, dy, da)
    end
  end
  self.odom = { odometry[1], odometry[2], odometry[3] }
  self.ball:predict(dt)
  if vision and vision.frame ~= self.frame then
    self.frame = vision.frame
    if vision.ball_detected then self.ball:observe(vision.ball[1], vision.ball[2], t) end
    local posts = self:plausible_posts(vision.posts)
    if posts then self.pose:observe_posts(posts) end
    if vision.robots then self:observe_robots(vision.robots, t) end
  end
  self.pose:estimate()
  self:forget_obstacles(t, dt, view)
end

-- The obstacles (robot frame) after the robot moved (dx, dy) and turned da: as the ball.
function World:move_obstacles(dx, dy, da)
  local c, s = cos(-da), sin(-da)
  for _, o in ipairs(self.obstacles) do
    local x, y = o.x - dx, o.y - dy
    o.x, o.y = c * x - s * y, s * x + c * y
  end
end

-- Robots seen in a frame ({ { x, y, team, foot_visible } ... }, robot frame): each updates the obstacle it is
-- near (within obstacle_merge m) or is a new one; a robot that the pose puts off the field (the
-- floor beyond the carpet looks the same to the vision) is dropped once the pose is trusted, and
-- so is one nearer than min_range (the robot's own feet and arms, seen looking down).
function World:observe_robots(list, t)
  local oc = self.cfg.obstacles
  local obs = self.obstacles
  local hl, hw = self.cfg.field.length / 2 + oc.field_margin, self.cfg.field.width / 2 + oc.field_margin
  local p = self.pose
  local c, s = cos(p.a), sin(p.a)
  for _, r in ipairs(list) do
    local fx, fy = p.x + c * r.x - s * r.y, p.y + s * r.x + c * r.y
    if r.x * r.x + r.y * r.y >= oc.min_range ^ 2 and (not self:localised()
      or (math.abs(fx) <= hl and math.abs(fy) <= hw)) then
      local best, bd = nil, oc.merge ^ 2
      for _, o in ipairs(obs) do
        local d = (o.x - r.x) ^ 2 + (o.y - r.y) ^ 2
        if d < bd then best, bd = o, d end
      end
      if best then
        local sx, sy = r.x, r.y
        if r.foot_visible == false then
          -- its feet below the image (a robot near, the head looking further): the image's bottom
          -- row's ground point is beyond them, so the sighting's range is only an upper bound; its
          -- bearing holds, the range stays the obstacle's when that is nearer
          local rr, ro = sqrt(sx * sx + sy * sy), sqrt(best.x * best.x + best.y * best.y)
          if ro < rr and rr > 0 then sx, sy = sx * ro / rr, sy * ro / rr end
        end
        best.x, best.y = best.x + oc.blend * (sx - best.x), best.y + oc.blend * (sy - best.y)
        best.t, best.missed = t, 0
        if r.team >= 0 then best.team = r.team end
      elseif #obs < oc.max then
        obs[#obs + 1] = { x = r.x, y = r.y, team = r.team, t = t, missed = 0 }
      end
    end
  end
end

-- Obstacles are forgotten (they walk away) after `memory` s in the camera's view without a
-- sighting, or `memory_out_of_view` s without one at all: a robot walked past stays known while it
-- is beside or behind us, where the camera cannot see it. Without a view (no head angle given),
-- every obstacle counts as in view.
function World:forget_obstacles(t, dt, view)
  local oc = self.cfg.obstacles
  local obs, k = self.obstacles, 1
  for i = 1, #obs do
    local o = obs[i]
    if o.t < t and (not view or math.abs(wrap(atan2(o.y, o.x) - view.pan)) < view.half_fov) then
      o.missed = o.missed + dt
    end
    local in_view_for = view and o.missed or (t - o.t)
    if in_view_for <= oc.memory and t - o.t <= oc.memory_out_of_view then
      obs[k] = o
      k = k + 1
    end
  end
  for i = #obs, k, -1 do obs[i] = nil end
end

-- The sightings worth giving the pose filter: none nearer than a robot can stand to a post or
-- further than ranges are trusted, and a pair only when its spacing fits a goal's width (false
-- posts from lines and robots are common).
function World:plausible_posts(posts)
  if not posts or #posts == 0 then return nil end
  local min_r = self.cfg.post_min_range
  local out = {}
  for _, p in ipairs(posts) do
    local r = sqrt(p[1] * p[1] + p[2] * p[2])
    if r >= min_r and r <= self.cfg.post_max_range then out[#out + 1] = p end
  end
  if #out == 2 then
    local sep = sqrt((out[1][1] - out[2][1]) ^ 2 + (out[1][2] - out[2][2]) ^ 2)
    if math.abs(sep - self.cfg.field.goal_width) > self.cfg.post_pair_tolerance then return nil end
  end
  if #out == 0 then return nil end
  self.posts_used = (self.posts_used or 0) + #out
  return out
end

-- Whether the pose is good enough to attack by: one confident hypothesis.
function World:localised()
  return self.pose.confidence >= self.cfg.localised_confidence
end

-- Seconds since the ball was last seen.
function World:ball_age()
  return (self.t or 0) - self.ball.t_seen
end

function World:ball_known()
  return self:ball_age() < self.cfg.ball_lost_after
end

-- The ball in the field frame (from the pose estimate).
function World:ball_field()
  local p = self.pose
  local c, s = cos(p.a), sin(p.a)
  return p.x + c * self.ball.x - s * self.ball.y, p.y + s * self.ball.x + c * self.ball.y
end

-- The ball in the walk's odometry frame (the motion block's cumulative odometry): still while the
-- ball is, whatever the pose belief does (the kick-off's "has the ball moved").
function World:ball_odometry()
  local o = self.odom or { 0, 0, 0 }
  local c, s = cos(o[3]), sin(o[3])
  return o[1] + c * self.ball.x - s * self.ball.y, o[2] + s * self.ball.x + c * self.ball.y
end

-- A field point in the robot frame.
function World:to_robot(fx, fy)
  local p = self.pose
  local ddx, ddy = fx - p.x, fy - p.y
  local c, s = cos(-p.a), sin(-p.a)
  return c * ddx - s * ddy, s * ddx + c * ddy
end

-- Centre of the opponent goal (x = +length/2) in the robot frame.
function World:goal_in_robot_frame()
  return self:to_robot(self.cfg.field.length / 2, 0)
end

-- The ball on the field as the team knows it: our own estimate while we know it, else the
-- youngest of the teammates' (world.mates, Player/Team/team.lua); nil when nobody knows.
function World:shared_ball()
  if self:ball_known() then
    local x, y = self:ball_field()
    return { x, y }, 'own'
  end
  local best
  for _, m in ipairs(self.mates or {}) do
    if m.ball_known and (not best or m.age < best.age) then best = m end
  end
  if best then return { best.ball[1], best.ball[2] }, 'team' end
  return nil
end

-- Writes the world block (one locked write).
function World:publish(block)
  local b, p = self.ball, self.pose
  block:write(function(w)
    w.ball[0], w.ball[1], w.ball[2], w.ball[3] = b.x, b.y, b.vx, b.vy
    w.ball_time[0] = b.seen and b.t_seen or -1
    w.pose[0], w.pose[1], w.pose[2] = p.x, p.y, p.a
    w.pose_confidence[0] = p.confidence
    w.pose_side[0] = p.side_a or 0 / 0
    w.time[0] = self.t or 0
    -- a sample of the particles for the live view (Run/view): every k-th, at most what the block holds
    local k = math.ceil(p.n / PARTICLES_SHOWN)
    local m = 0
    for i = 1, p.n, k do
      w.particles[3 * m], w.particles[3 * m + 1], w.particles[3 * m + 2] = p.px[i], p.py[i], p.pa[i]
      m = m + 1
    end
    w.nparticles[0] = m
    local obs = self.obstacles
    local n = math.min(#obs, 8) -- the block holds 8 (Config/shm.schema)
    w.obstacles[0] = n
    for i = 1, n do
      w.obstacle[2 * i - 2], w.obstacle[2 * i - 1] = obs[i].x, obs[i].y
      w.obstacle_team[i - 1] = obs[i].team
      w.obstacle_age[i - 1] = (self.t or 0) - obs[i].t
    end
  end)
end

-- Bearing and distance of a robot-frame point.
function M.polar(x, y) return sqrt(x * x + y * y), atan2(y, x) end

return M
