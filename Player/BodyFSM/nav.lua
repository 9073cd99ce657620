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

-- The point to walk to: behind the ball on the line from the goal, going round the ball when the
-- robot is on its far side. Returns tx, ty, heading wanted (robot frame).
function M.behind_ball(ctx)
  local cfg = ctx.cfg.body
  local bx, by, ux, uy = M.attack(ctx)
  local r = cfg.approach_behind
  local tx, ty = bx - r * ux, by - r * uy
  local along = bx * ux + by * uy -- how far the ball is ahead of the robot along the attack line
  if along < 0.15 then
    -- the robot is level with or beyond the ball: pass beside it, on the robot's side
    local px, py = -uy, ux
    local side = (-(bx * px + by * py)) >= 0 and 1 or -1
    tx, ty = bx - 0.5 * r * ux + side * 0.45 * px, by - 0.5 * r * uy + side * 0.45 * py
  end
  return tx, ty, atan2(uy, ux)
end

-- Velocity towards (tx, ty) (robot frame) ending with heading `ha` (robot frame, rad).
-- Far away: face the target and walk; near: turn to ha while side-stepping.
function M.go_to(ctx, tx, ty, ha)
  local cfg = ctx.cfg.body
  local d = sqrt(tx * tx + ty * ty)
  local bearing = atan2(ty, tx)
  local vx, vy, va
  if d > 0.6 then
    va = 1.2 * bearing
    vx = cfg.approach_speed * math.max(0, cos(bearing)) ^ 2
    vy = 0.3 * ty
  else
    local blend = d / 0.6
    va = 1.0 * wrap((1 - blend) * (ha or bearing) + blend * bearing)
    vx = 0.8 * tx
    vy = 0.8 * ty
  end
  return clamp(vx, -0.1, cfg.max_vx), clamp(vy, -cfg.max_vy, cfg.max_vy),
    clamp(va, -cfg.max_va, cfg.max_va), d
end

-- The field point (fx, fy) in the robot frame.
function M.field_to_robot(ctx, fx, fy)
  return ctx.world:to_robot(fx, fy)
end

M.sin, M.cos = sin, cos
return M
