-- Initial: stand still, head straight ahead.
local M = {}

function M.entry(ctx)
  ctx.body:event('stop', ctx)
  ctx.head:event('reset', ctx)
end

function M.update(ctx)
  ctx.act.stop()
  ctx.act.head(0, 0)
end

-- Leaving initial: the robot has been placed in its own half; localize afresh from there.
function M.exit(ctx)
  if ctx.world and ctx.world.reset_pose then ctx.world:reset_pose() end
end

return M
