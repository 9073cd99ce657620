-- Finished: stand still.
local M = {}

function M.entry(ctx) ctx.body:event('stop', ctx) end
function M.update(ctx) ctx.act.stop() ctx.act.head(0, 0) end

return M
