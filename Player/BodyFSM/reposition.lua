-- The ball is lost: walk back towards where it was last estimated (field frame), then search.
local nav = require('BodyFSM.nav')

local M = {}
local fx, fy, t0

function M.entry(ctx)
  fx, fy = ctx.world:ball_field()
  t0 = ctx.t
end

function M.update(ctx)
  local cfg = ctx.cfg.body
  if ctx.world:ball_age() < 0.3 then return 'ball' end
  local tx, ty = nav.field_to_robot(ctx, fx, fy)
  -- stop short of it: from there the head can see it
  local d = math.sqrt(tx * tx + ty * ty)
  if d < cfg.reposition_near or ctx.t - t0 > cfg.reposition_timeout then return 'done' end
  local vx, vy, va = nav.go_to(ctx, tx, ty, nil)
  ctx.act.walk(vx, vy, va)
end

return M
