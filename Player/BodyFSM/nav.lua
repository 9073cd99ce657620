-- Walking helpers shared by the body states: where to stand behind the ball, and velocity commands.
local M = {}

local sqrt, atan2, cos, sin = math.sqrt, math.atan2, math.cos, math.sin

local function clamp(x, lo, hi) if x < lo then return lo elseif x > hi then return hi end return x end
M.clamp = clamp

local function wrap(a) return (a + math.pi) % (2 * math.pi) - math.pi end
M.wrap = wrap

-- The ball and the attack direction in the robot frame: bx, by, ux, uy (unit vector ball -> goal).
function M.attack(ctx)
  local w = ctx.world
  local bx, by = w.ball.x, w.ball.y
  -- aim behind the goal line: a pose estimate a little too far forward then still attacks forward
  local gx, gy = w:to_robot(w.cfg.field.length / 2 + (ctx.cfg.body.attack_depth or 0), 0)
  local dx, dy = gx - bx, gy - by
  local d = sqrt(dx * dx + dy * dy)
  if d < 1e-6 then return bx, by, 1, 0, 0 end
  return bx, by, dx / d, dy / d, d
end

-- Whether the ball's estimate lies in a goal: beyond either goal line by body.ball_in_goal.beyond m, inside
-- the posts by .inside m (a scored ball; trusted only with the pose, and not within .retry s of giving up
-- a wait: BodyFSM/wait.lua sets ctx.in_goal_gave_up).
function M.ball_in_goal(ctx)
  local w = ctx.world
  local g = ctx.cfg.body.ball_in_goal
  if not w:localised() or ctx.t - (ctx.in_goal_gave_up or -math.huge) < g.retry then return false end
  local fx, fy = w:ball_field()
  local f = w.cfg.field
  return math.abs(fx) > f.length / 2 + g.beyond and math.abs(fy) < f.goal_width / 2 - g.inside
end

-- The point to walk to: behind the ball on the line from the goal, going round the ball when the
-- robot is on its far side. Returns tx, ty, heading wanted (robot frame).
function M.behind_ball(ctx)
  local cfg = ctx.cfg.body
  local bx, by, ux, uy = M.attack(ctx)
  local r, nv = cfg.approach_behind, cfg.nav
  local tx, ty = bx - r * ux, by - r * uy
  local along = bx * ux + by * uy -- how far the ball is ahead of the robot along the attack line
  if along < nv.pass_along then
    -- the robot is level with or beyond the ball: pass beside it, on the robot's side
    local px, py = -uy, ux
    local side = (-(bx * px + by * py)) >= 0 and 1 or -1
    local back, off = nv.pass_behind * r, side * nv.pass_side
    tx, ty = bx - back * ux + off * px, by - back * uy + off * py
  end
  return tx, ty, atan2(uy, ux)
end

-- The robots to keep clear of (robot frame): those seen (world.obstacles) and the teammates heard
-- within `mate_age` s (world.mates, their own pose estimates), once our pose is trusted: a
-- teammate is then known even when the camera does not see it or cannot tell its colour.
function M.robots(ctx)
  local w = ctx.world
  local obs = w.obstacles
  if not w.mates or #w.mates == 0 or not w:localised() then return obs end
  local list = {}
  for i, o in ipairs(obs or {}) do list[i] = o end
  local max_age = ctx.cfg.body.nav.avoid.mate_age
  for _, m in ipairs(w.mates) do
    if m.age <= max_age and not m.penalised then
      local x, y = w:to_robot(m.pose[1], m.pose[2])
      list[#list + 1] = { x = x, y = y, team = 'mate' }
    end
  end
  return list
end

-- The point to steer for on the way to (tx, ty) (robot frame): the target itself, or, when another
-- robot (M.robots: seen, its foot point, or a teammate's reported pose) stands in the way, a point
-- on the tangent to a circle of `clearance` m around it. In the way: nearer the straight path than
-- `clearance`, from `behind` m behind the robot (beside it: still in the way) to `short` m before
-- the target. The side is the one away from the obstacle's offset from the path, kept
-- (ctx.avoid_side) until the way is clear, so that the robot does not swing between the two.
-- Inside the circle: straight away from it, sideways.
function M.avoid(ctx, tx, ty)
  local obs = M.robots(ctx)
  local d = sqrt(tx * tx + ty * ty)
  local av = ctx.cfg.body.nav.avoid
  if not obs or #obs == 0 or d < av.min_distance then ctx.avoid_side = nil return tx, ty end
  local ux, uy = tx / d, ty / d
  local bt = atan2(ty, tx)
  local best, best_d
  for _, o in ipairs(obs) do
    local od = sqrt(o.x * o.x + o.y * o.y)
    local along, across = o.x * ux + o.y * uy, -o.x * uy + o.y * ux
    if along > -av.behind and along < d - av.short and math.abs(across) < av.clearance
      and (not best or od < best_d) then
      best, best_d = o, od
    end
  end
  if not best then ctx.avoid_side = nil return tx, ty end
  local bo = atan2(best.y, best.x)
  -- +1: pass on its left (it on our right)
  local side = ctx.avoid_side or (wrap(bt - bo) >= 0 and 1 or -1)
  ctx.avoid_side = side
  local cone = best_d > av.clearance and math.asin(av.clearance / best_d) or math.pi / 2
  local th = bo + side * (cone + av.margin)
  local r = math.max(best_d, av.clearance)
  return r * cos(th), r * sin(th)
end

-- Velocity towards (tx, ty) (robot frame) ending with heading `ha` (robot frame, rad), stepping
-- around a robot in the way (M.avoid). Far away: face the target and walk; near: turn to ha while
-- side-stepping. The distance returned is the target's.
function M.go_to(ctx, tx, ty, ha)
  local cfg = ctx.cfg.body
  local nv = cfg.nav
  local d = sqrt(tx * tx + ty * ty)
  local wx, wy = M.avoid(ctx, tx, ty)
  if wx ~= tx or wy ~= ty then
    -- round the obstacle: walk to the waypoint, facing it
    local bearing = atan2(wy, wx)
    return clamp(cfg.approach_speed * math.max(0, cos(bearing)) ^ 2, nv.min_vx, cfg.max_vx),
      clamp(nv.far_side_gain * wy, -cfg.max_vy, cfg.max_vy),
      clamp(nv.far_turn_gain * bearing, -cfg.max_va, cfg.max_va), d
  end
  local bearing = atan2(ty, tx)
  local vx, vy, va
  if d > nv.near then
    va = nv.far_turn_gain * bearing
    vx = cfg.approach_speed * math.max(0, cos(bearing)) ^ 2
    vy = nv.far_side_gain * ty
  else
    local blend = d / nv.near
    va = nv.near_turn_gain * wrap((1 - blend) * (ha or bearing) + blend * bearing)
    vx = nv.near_gain * tx
    vy = nv.near_gain * ty
  end
  return clamp(vx, nv.min_vx, cfg.max_vx), clamp(vy, -cfg.max_vy, cfg.max_vy),
    clamp(va, -cfg.max_va, cfg.max_va), d
end

-- The field point (fx, fy) in the robot frame.
function M.field_to_robot(ctx, fx, fy)
  return ctx.world:to_robot(fx, fy)
end

M.sin, M.cos = sin, cos
return M
