-- Walk towards the reposition point (a place with a view of the field), looking for the ball.
local nav = require('BodyFSM.nav')
local fsm = require('fsm')

local M = {}

-- per activation (ctx): t0 (entry time)
function M.entry(ctx) fsm.fresh(ctx, 'BodyFSM.wander').t0 = ctx.t end

function M.update(ctx)
  local cfg = ctx.cfg.body
  if ctx.world:ball_age() < 0.3 then return 'ball' end
  local tx, ty = nav.field_to_robot(ctx, cfg.reposition[1], cfg.reposition[2])
  local vx, vy, va, d = nav.go_to(ctx, tx, ty, nil)
  if d < cfg.wander_arrive then vx, vy, va = 0, 0, cfg.search_turn_speed end
  ctx.act.walk(vx, vy, va)
  if ctx.t - fsm.data(ctx, 'BodyFSM.wander').t0 > cfg.wander_time then return 'timeout' end
end

return M
