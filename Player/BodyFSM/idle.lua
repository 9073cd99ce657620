-- Stand still (before play, while penalized, when vision is down).
local M = {}

function M.entry(ctx) ctx.act.stop() end
function M.update(ctx) ctx.act.stop() end

return M
