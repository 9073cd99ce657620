-- Look for goal posts: towards where the opponent goal should be when the pose is trusted;
-- otherwise one sweep across the head's whole range at the far row (the estimate's goal direction
-- would be a guess), then back to the ball.
local point = require('HeadFSM.point')
local fsm = require('fsm')

local M = {}

-- per activation (ctx): t0 (entry time), sweep (a sweep, not a look at the goal), from (+1: the
-- sweep starts on the left)
function M.entry(ctx)
  local d = fsm.fresh(ctx, 'HeadFSM.lookgoal')
  d.t0 = ctx.t
  d.sweep = not ctx.world:localised()
  -- sweep from the side the head is nearer to (the ball's side)
  d.from = (ctx.world.ball.y >= 0) and 1 or -1
end

function M.update(ctx)
  local cfg = ctx.cfg.head
  local d = fsm.data(ctx, 'HeadFSM.lookgoal')
  local sweep, from = d.sweep, d.from
  local dt = ctx.t - d.t0
  -- the body aims a kick at the ball: back to it (its place goes stale while the head is away)
  if ctx.keep_ball and not sweep then return 'done' end
  local pan, tilt
  if sweep then
    local u = math.min(1, dt / cfg.look_around_time)
    local bearing = from * (1 - 2 * u) * cfg.scan_pan
    local far = cfg.scan_distances[1]
    pan, tilt = point.ground(far * math.cos(bearing), far * math.sin(bearing), cfg)
    if dt > cfg.look_around_time then return 'done' end
  else
    local gx, gy = ctx.world:goal_in_robot_frame()
    local dist = math.sqrt(gx * gx + gy * gy)
    -- beyond the head's reach (goal behind): the side the goal is on
    local r = cfg.goal_look_distance
    pan, tilt = point.ground(gx / dist * r, gy / dist * r, cfg)
    if dt > cfg.look_goal_time then return 'done' end
  end
  ctx.act.head(pan, tilt)
end

return M
