-- Kick with the foot on the ball's side; without a kick (or when it is refused) walk through the ball.
local M = {}
local t0, kicked, seen_kick

function M.entry(ctx)
  t0 = ctx.t
  seen_kick = false
  kicked = ctx.cfg.body.use_kick and ctx.act.kick(ctx.kick_side or 'left')
end

function M.update(ctx)
  local cfg = ctx.cfg.body
  if kicked then
    local s = ctx.act.motion_state() or ''
    if s:find('kick') then seen_kick = true end
    if (seen_kick and not s:find('kick')) or ctx.t - t0 > cfg.kick_timeout then return 'done' end
  else
    -- dribble: walk into the ball towards the goal for a moment
    ctx.act.walk(cfg.max_vx, 0, 0)
    if ctx.t - t0 > 1.5 then return 'done' end
  end
end

return M
