-- Turn on the spot (towards where the ball was last) until it is seen; then wander.
local M = {}
local t0, dir

function M.entry(ctx)
  t0 = ctx.t
  dir = (ctx.world.ball.y >= 0) and 1 or -1
end

function M.update(ctx)
  local cfg = ctx.cfg.body
  if ctx.world:ball_age() < 0.3 then return 'ball' end
  ctx.act.walk(0, 0, dir * cfg.search_turn_speed)
  if ctx.t - t0 > cfg.search_turn_time then return 'timeout' end
end

return M
