-- Set: stand still, keep the ball in view.
local M = {}

function M.entry(ctx) ctx.body:event('stop', ctx) end

function M.update(ctx)
  ctx.act.stop()
  ctx.head:update(ctx)
end

return M
