-- Look towards where the opponent goal should be (from the pose estimate), then back to the ball.
local point = require('HeadFSM.point')

local M = {}
local t0

function M.entry(ctx) t0 = ctx.t end

function M.update(ctx)
  local cfg = ctx.cfg.head
  local gx, gy = ctx.world:goal_in_robot_frame()
  local d = math.sqrt(gx * gx + gy * gy)
  -- beyond the head's reach (goal behind): sweep to the side the goal is on
  local pan, tilt = point.ground(gx / d * 3.0, gy / d * 3.0, cfg.ground_z)
  ctx.act.head(pan, tilt)
  if ctx.t - t0 > cfg.look_goal_time then return 'done' end
end

return M
