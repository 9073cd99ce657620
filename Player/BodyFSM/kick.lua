-- Kick with the foot on the ball's side: while walking, a kick out of the walk (the walk goes on,
-- config body.walk_kick); standing, the kick motion; without a kick (or when it is refused) walk
-- through the ball.
local fsm = require('fsm')

local M = {}

-- per activation (ctx): t0 (entry time), walking (a kick out of the walk), kicked (asked for; the
-- kick motion started), seen_kick (the kick motion seen running), kicks0 (the walk's kicks at entry)

-- A request still waiting for its step when the state ends (its timeout) is dropped: re-asked up to
-- the last tick, it would otherwise stay live for walkKick.expire and strike later at a stale place.
function M.exit(ctx)
  local d = fsm.data(ctx, 'BodyFSM.kick')
  ctx.keep_ball = nil
  if d.walking and d.kicked and ctx.act.walk_kick_phase() == 'asked' then ctx.act.walk_kick_cancel() end
end

function M.entry(ctx)
  local cfg = ctx.cfg.body
  local d = fsm.fresh(ctx, 'BodyFSM.kick')
  d.t0 = ctx.t
  d.seen_kick = false
  local wk = cfg.walk_kick
  d.walking = wk and wk.enabled and ctx.act.motion_state() == 'walk'
  if d.walking then
    d.kicks0 = ctx.act.walk_kicks()
    d.kicked = false
    -- the head stays on the ball (no look at the goal): the strike is aimed at its place
    ctx.keep_ball = wk.keep_ball
  else
    d.kicked = cfg.use_kick and ctx.act.kick(ctx.kick_side or 'left')
  end
end

function M.update(ctx)
  local cfg = ctx.cfg.body
  local d = fsm.data(ctx, 'BodyFSM.kick')
  if d.walking then
    -- walk on straight; the kick is asked for once the walk is as slow as the kick is made for
    -- (a kick step out of a faster walk throws the robot back), the walk takes it on its next step
    local wk = cfg.walk_kick
    local b = ctx.world.ball
    -- a ball rolling on ahead (pushed while dribbling) is closed on first: the walk slows to the
    -- kick's speed as the ball comes back to the zone's far end (close_gain 1/s; 0: slow at once)
    local vx = wk.speed
    if not d.kicked then
      vx = math.min(math.max(wk.speed + (wk.close_gain or 0) * (b.x - wk.x[2]), wk.speed), cfg.max_vx)
    end
    ctx.act.walk(vx, 0, 0)
    -- asked again each tick while the kick waits for its step, with the ball's place as last seen:
    -- a dribbled ball rolls on and sways, and the strike is aimed where it was asked for
    local fresh = ctx.world:ball_age() < wk.max_age
    if ctx.act.walk_velocity() <= wk.max_vx
      and (not d.kicked or (wk.follow and fresh and ctx.act.walk_kick_phase() == 'asked')) then
      d.kicked = ctx.act.walk_kick('forward', ctx.kick_side or (b.y >= 0 and 'left' or 'right'), b.x, b.y)
        or d.kicked
    end
    if ctx.act.walk_kicks() > d.kicks0 or ctx.t - d.t0 > wk.timeout then return 'done' end
  elseif d.kicked then
    local s = ctx.act.motion_state() or ''
    if s:find('kick') then d.seen_kick = true end
    if (d.seen_kick and not s:find('kick')) or ctx.t - d.t0 > cfg.kick_timeout then return 'done' end
  else
    -- dribble: walk into the ball towards the goal for a moment
    ctx.act.walk(cfg.max_vx, 0, 0)
    if ctx.t - d.t0 > 1.5 then return 'done' end
  end
end

return M
