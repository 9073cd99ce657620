-- The moves of the rules' set plays (Player/GameFSM/setplay.lua), one call per behavior step:
--   keep_away(ctx, d)  stay d (+ margin) from the ball facing it: back off when nearer
--   take(ctx)          walk behind the ball towards the opponent goal and stand there (no kick)
--   stand(ctx)         stand (the head keeps watching)
--   go_to(ctx, x, y, arrive)  walk to the field point (x, y), then turn to the ball and stand
--   guard(ctx)         the goalkeeper on its goal line's centre, facing the ball
local nav = require('BodyFSM.nav')

local M = {}
local sqrt, atan2, abs = math.sqrt, math.atan2, math.abs

-- Turn on the spot towards the ball when it is well off to the side, else stand.
local function face(ctx, bearing, gain)
  local cfg = ctx.cfg.body
  if abs(bearing) > 0.3 then ctx.act.walk(0, 0, nav.clamp(gain * bearing, -cfg.max_va, cfg.max_va))
  else ctx.act.stop() end
end

function M.keep_away(ctx, d)
  local w, sp, cfg = ctx.world, ctx.rules.setplay, ctx.cfg.body
  if not w:ball_known() then ctx.act.stop() return end
  local bx, by = w.ball.x, w.ball.y
  local r, bearing = sqrt(bx * bx + by * by), atan2(by, bx)
  -- back off until the distance plus the hysteresis, then stand until nearer than distance + margin
  local backing = ctx.keep_away_backing
  if r < d + sp.margin then backing = true elseif r > d + sp.margin + sp.hysteresis then backing = false end
  ctx.keep_away_backing = backing
  if backing and r > 1e-3 then
    local ux, uy = -bx / r, -by / r -- away from the ball
    ctx.act.walk(nav.clamp(sp.retreat_speed * ux, cfg.nav.min_vx, cfg.max_vx),
      nav.clamp(sp.retreat_speed * uy, -cfg.max_vy, cfg.max_vy),
      nav.clamp(sp.turn_gain * bearing, -cfg.max_va, cfg.max_va))
  else
    face(ctx, bearing, sp.turn_gain)
  end
end

function M.take(ctx)
  local w, sp = ctx.world, ctx.rules.setplay
  if not w:ball_known() then ctx.act.stop() return end
  local tx, ty, ha = nav.behind_ball(ctx)
  local vx, vy, va, dist = nav.go_to(ctx, tx, ty, ha)
  if dist < sp.take_tolerance and abs(ha) < ctx.cfg.body.kick_tolerance_angle then ctx.act.stop()
  else ctx.act.walk(vx, vy, va) end
end

function M.go_to(ctx, x, y, arrive)
  local w = ctx.world
  local tx, ty = w:to_robot(x, y)
  local d = sqrt(tx * tx + ty * ty)
  local bearing = w:ball_known() and atan2(w.ball.y, w.ball.x) or 0
  if d < arrive then face(ctx, bearing, ctx.rules.setplay.turn_gain) return end
  local vx, vy, va = nav.go_to(ctx, tx, ty, bearing)
  ctx.act.walk(vx, vy, va)
end

function M.guard(ctx)
  local field = ctx.world.cfg.field
  M.go_to(ctx, -field.length / 2 + ctx.rules.setplay.keeper_line, 0, ctx.rules.roles.arrive)
end

function M.stand(ctx)
  ctx.act.stop()
end

return M
