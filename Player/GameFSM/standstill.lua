-- Standing still, head straight ahead, the body and head machines stopped: the initial and the
-- penalized states. Leaving either, the robot may have been carried (placed for the game, put
-- back after a penalty): the pose belief restarts from the prior (anywhere in the own half).
local M = {}

function M.entry(ctx)
  ctx.body:event('stop', ctx)
  ctx.head:event('reset', ctx)
end

function M.update(ctx)
  ctx.act.stop()
  ctx.act.head(0, 0)
end

function M.exit(ctx)
  if ctx.world and ctx.world.reset_pose then ctx.world:reset_pose() end
end

return M
