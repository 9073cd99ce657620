-- After a kick: walk after the ball along the attack direction until it is seen again.
local fsm = require('fsm')

local M = {}

-- per activation (ctx): t0 (entry time)
function M.entry(ctx) fsm.fresh(ctx, 'BodyFSM.follow').t0 = ctx.t end

function M.update(ctx)
  local cfg = ctx.cfg.body
  local t0 = fsm.data(ctx, 'BodyFSM.follow').t0
  if ctx.t - t0 > 0.5 and ctx.world:ball_age() < 0.3 then return 'ball' end
  local b = ctx.world.ball
  local bearing = math.atan2(b.y, b.x)
  local speed = math.min(cfg.approach_speed, cfg.follow_speed)
  ctx.act.walk(speed * math.max(0, math.cos(bearing)), 0, cfg.follow_turn_gain * bearing)
  if ctx.t - t0 > cfg.follow_time then return 'timeout' end
end

return M
