-- Keep the camera on the ball (the world model's estimate); every so often look at the goal.
local point = require('HeadFSM.point')

local M = {}
local t0

function M.entry(ctx) t0 = ctx.t end

function M.update(ctx)
  local cfg = ctx.cfg.head
  local w = ctx.world
  if w:ball_age() > 1.5 then return 'lost' end
  local b = w.ball
  local pan, tilt = point.ground(b.x, b.y, cfg.ground_z)
  ctx.act.head(pan, tilt)
  local dist = math.sqrt(b.x * b.x + b.y * b.y)
  if ctx.t - t0 > cfg.look_goal_every and dist > cfg.look_goal_min_distance and ctx.look_goal_allowed then
    return 'timeout'
  end
end

return M
