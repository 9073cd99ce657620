-- Keep the camera on the ball (the world model's estimate); every so often look for the goal:
-- more often while the pose is not trusted, or near the opponent goal (where aiming needs it),
-- and at once when the body asks (ctx.look_around); never while the body needs the ball's place
-- fresh (ctx.keep_ball: a kick out of the walk aims its strike at it).
local point = require('HeadFSM.point')
local fsm = require('fsm')

local M = {}

-- per activation (ctx): t0 (entry time, or the last look at the goal's end)
function M.entry(ctx) fsm.fresh(ctx, 'HeadFSM.track').t0 = ctx.t end

function M.update(ctx)
  local cfg = ctx.cfg.head
  local w = ctx.world
  local t0 = fsm.data(ctx, 'HeadFSM.track').t0
  -- (back from a look at the goal, the head needs a moment to find the ball again)
  if w:ball_age() > 1.5 and ctx.t - t0 > 0.8 and not ctx.look_around then return 'lost' end
  -- a body state that knows better where an unseen ball is (dribbling: ahead of the feet) says so
  local hint = ctx.ball_hint
  local bx, by = w.ball.x, w.ball.y
  if hint then bx, by = hint[1], hint[2] end
  local pan, tilt = point.ground(bx, by, cfg)
  ctx.act.head(pan, tilt)
  local every = cfg.look_goal_every
  if ctx.look_around or not w:localised() then
    every = cfg.look_goal_every_lost
  else
    local gx, gy = w:goal_in_robot_frame()
    if gx * gx + gy * gy < cfg.near_goal ^ 2 then every = cfg.look_goal_every_near end
  end
  if ctx.t - t0 > every and not ctx.keep_ball then return 'timeout' end
end

return M
