-- Penalized: stand still until released; then the search starts afresh.
local M = {}

function M.entry(ctx)
  ctx.body:event('stop', ctx)
  ctx.head:event('reset', ctx)
end

function M.update(ctx)
  ctx.act.stop()
  ctx.act.head(0, 0)
end

return M
