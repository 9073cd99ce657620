-- The ball is lost: walk back towards where it was last estimated (field frame), then search.
local nav = require('BodyFSM.nav')

local M = {}
local fx, fy, t0

function M.entry(ctx)
  fx, fy = ctx.world:ball_field()
  t0 = ctx.t
end

function M.update(ctx)
  if ctx.world:ball_age() < 0.3 then return 'ball' end
  local tx, ty = nav.field_to_robot(ctx, fx, fy)
  -- stop short of it: from a metre away the head can see it
  local d = math.sqrt(tx * tx + ty * ty)
  if d < 1.0 or ctx.t - t0 > 10 then return 'done' end
  local vx, vy, va = nav.go_to(ctx, tx, ty, nil)
  ctx.act.walk(vx, vy, va)
end

return M
