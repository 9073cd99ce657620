-- Kick with the foot on the ball's side: while walking, a kick out of the walk (the walk goes on,
-- config body.walk_kick); standing, the kick motion; without a kick (or when it is refused) walk
-- through the ball.
local M = {}
local t0, kicked, seen_kick, walking, kicks0

-- A request still waiting for its step when the state ends (its timeout) is dropped: re-asked up to
-- the last tick, it would otherwise stay live for walkKick.expire and strike later at a stale place.
function M.exit(ctx)
  ctx.keep_ball = nil
  if walking and kicked and ctx.act.walk_kick_phase() == 'asked' then ctx.act.walk_kick_cancel() end
end

function M.entry(ctx)
  local cfg = ctx.cfg.body
  t0 = ctx.t
  seen_kick = false
  local wk = cfg.walk_kick
  walking = wk and wk.enabled and ctx.act.motion_state() == 'walk'
  if walking then
    kicks0 = ctx.act.walk_kicks()
    kicked = false
    -- the head stays on the ball (no look at the goal): the strike is aimed at its place
    ctx.keep_ball = wk.keep_ball
  else
    kicked = cfg.use_kick and ctx.act.kick(ctx.kick_side or 'left')
  end
end

function M.update(ctx)
  local cfg = ctx.cfg.body
  if walking then
    -- walk on straight; the kick is asked for once the walk is as slow as the kick is made for
    -- (a kick step out of a faster walk throws the robot back), the walk takes it on its next step
    local wk = cfg.walk_kick
    local b = ctx.world.ball
    -- a ball rolling on ahead (pushed while dribbling) is closed on first: the walk slows to the
    -- kick's speed as the ball comes back to the zone's far end (close_gain 1/s; 0: slow at once)
    local vx = wk.speed
    if not kicked then
      vx = math.min(math.max(wk.speed + (wk.close_gain or 0) * (b.x - wk.x[2]), wk.speed), cfg.max_vx)
    end
    ctx.act.walk(vx, 0, 0)
    -- asked again each tick while the kick waits for its step, with the ball's place as last seen:
    -- a dribbled ball rolls on and sways, and the strike is aimed where it was asked for
    local fresh = ctx.world:ball_age() < wk.max_age
    if ctx.act.walk_velocity() <= wk.max_vx
      and (not kicked or (wk.follow and fresh and ctx.act.walk_kick_phase() == 'asked')) then
      kicked = ctx.act.walk_kick('forward', ctx.kick_side or (b.y >= 0 and 'left' or 'right'), b.x, b.y)
        or kicked
    end
    if ctx.act.walk_kicks() > kicks0 or ctx.t - t0 > wk.timeout then return 'done' end
  elseif kicked then
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
