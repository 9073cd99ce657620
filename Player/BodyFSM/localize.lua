-- The pose is not trusted (attacking by it could carry the ball anywhere): stand while the head
-- looks for goal posts (ctx.look_around); turn on the spot after a while (posts out of the head's
-- reach); give up after localize_timeout and go on with the best guess.
local fsm = require('fsm')

local M = {}

-- per activation (ctx): t0 (entry time)
function M.entry(ctx)
  fsm.fresh(ctx, 'BodyFSM.localize').t0 = ctx.t
  ctx.look_around = true
end

function M.exit(ctx)
  ctx.look_around = false
end

function M.update(ctx)
  local cfg = ctx.cfg.body
  if ctx.world:localised() then return 'done' end
  local dt = ctx.t - fsm.data(ctx, 'BodyFSM.localize').t0
  if dt > cfg.localize_timeout then
    ctx.localize_gave_up = ctx.t
    return 'done'
  end
  if dt > cfg.localize_turn_after then ctx.act.walk(0, 0, cfg.search_turn_speed) else ctx.act.stop() end
end

-- Whether a state that attacks by the pose should stop and localize first.
function M.needed(ctx)
  local cfg = ctx.cfg.body
  return ctx.world.pose.confidence < cfg.relocalise_below
    and ctx.t - (ctx.localize_gave_up or -math.huge) > cfg.localize_retry_after
end

return M
