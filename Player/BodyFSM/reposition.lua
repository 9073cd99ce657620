-- The ball is lost: walk back towards where it was last estimated (field frame), then search.
local nav = require('BodyFSM.nav')
local fsm = require('fsm')

local M = {}

-- per activation (ctx): fx, fy (the ball's last estimate, field frame), t0 (entry time)
function M.entry(ctx)
  local d = fsm.fresh(ctx, 'BodyFSM.reposition')
  d.fx, d.fy = ctx.world:ball_field()
  d.t0 = ctx.t
end

function M.update(ctx)
  local cfg = ctx.cfg.body
  local d = fsm.data(ctx, 'BodyFSM.reposition')
  if ctx.world:ball_age() < 0.3 then return 'ball' end
  local tx, ty = nav.field_to_robot(ctx, d.fx, d.fy)
  -- stop short of it: from there the head can see it
  local dist = math.sqrt(tx * tx + ty * ty)
  if dist < cfg.reposition_near or ctx.t - d.t0 > cfg.reposition_timeout then return 'done' end
  local vx, vy, va = nav.go_to(ctx, tx, ty, nil)
  ctx.act.walk(vx, vy, va)
end

return M
