-- Turn on the spot (towards where the ball was last) until it is seen; then wander. A ball lost at
-- the feet (below or behind the camera's view) is looked for by stepping back first: turning on
-- the spot would keep it there, and push it about. A ball never seen yet (nothing says which way
-- to turn) is looked for standing first, for search_look_time s while the head sweeps its whole
-- range once (HeadFSM/scan.lua, restarted by ctx.scan_restart): the turn sweeps only the view
-- straight ahead, and a ball beside the robot the turn went away from was found only after a
-- whole turn.
local fsm = require('fsm')

local M = {}

-- per activation (ctx): dir (+1: turn left), back_until and look_until (s: stepping back, then
-- standing to look, until then)
function M.entry(ctx)
  local cfg = ctx.cfg.body
  local d = fsm.fresh(ctx, 'BodyFSM.search')
  local t0 = ctx.t
  local b = ctx.world.ball
  d.dir = (b.y >= 0) and 1 or -1
  local near = b.seen and b.x * b.x + b.y * b.y < cfg.search_back_near ^ 2
  d.back_until = near and t0 + cfg.search_back_time or t0
  d.look_until = d.back_until
  if not b.seen and (cfg.search_look_time or 0) > 0 then
    d.look_until = t0 + cfg.search_look_time
    ctx.scan_restart = t0
  end
end

function M.exit(ctx) ctx.body_turning = nil end

function M.update(ctx)
  local cfg = ctx.cfg.body
  local d = fsm.data(ctx, 'BodyFSM.search')
  if ctx.world:ball_age() < 0.3 then return 'ball' end
  if ctx.t < d.back_until then
    ctx.act.walk(-cfg.search_back_speed, 0, 0)
  elseif ctx.t < d.look_until then
    ctx.act.walk(0, 0, 0)
  else
    ctx.act.walk(0, 0, d.dir * cfg.search_turn_speed)
    ctx.body_turning = true
  end
  if ctx.t - d.look_until > cfg.search_turn_time then return 'timeout' end
end

return M
