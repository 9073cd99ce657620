-- Playing: the body and head machines run; with no fresh vision the robot stands and waits.
local M = {}

function M.entry(ctx)
  ctx.body:event('start', ctx)
end

function M.update(ctx)
  if ctx.vision_stale then
    if ctx.body:state() ~= 'idle' then ctx.body:event('stop', ctx) end
    ctx.act.stop()
    return
  end
  if ctx.body:state() == 'idle' then ctx.body:event('start', ctx) end
  ctx.body:update(ctx)
  ctx.head:update(ctx)
end

return M
