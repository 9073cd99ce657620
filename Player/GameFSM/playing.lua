-- Playing: the body and head machines run, within what the rules allow now (GameFSM.setplay: the
-- other team's kick-off and set plays keep us away from the ball, ours wait for the referee's
-- execute) and as the robot's role says (Team.roles: the striker plays the ball, the others keep
-- their positions, Team.position); with no fresh vision the robot stands and waits.
local setplay = require('GameFSM.setplay')
local moves = require('GameFSM.moves')
local position = require('Team.position')

local M = {}

function M.entry(ctx)
  ctx.body:event('start', ctx)
end

-- The kick-off's progress: time in PLAYING since it began and whether the ball has moved from
-- where it was first seen (in the odometry frame: a pose belief that settles does not move it).
local function kickoff_progress(ctx)
  local k = ctx.kickoff
  if not k then return nil end
  k.since = ctx.t - k.t0
  -- only sightings from the kick-off on (an older estimate may be of where the ball was before
  -- it was placed)
  if not k.ball_moved and ctx.world.ball.t_seen >= k.t0 then
    local x, y = ctx.world:ball_odometry()
    if not k.ball0 then k.ball0 = { x, y }
    elseif (x - k.ball0[1]) ^ 2 + (y - k.ball0[2]) ^ 2 > ctx.rules.kickoff.ball_moved ^ 2 then
      k.ball_moved = true
    end
  end
  return k
end

function M.update(ctx)
  if ctx.vision_stale then
    if ctx.body:state() ~= 'idle' then ctx.body:event('stop', ctx) end
    ctx.act.stop()
    return
  end
  local mode, distance = setplay.decide(ctx.game, ctx.rules, kickoff_progress(ctx), ctx.role)
  ctx.setplay = mode
  local x, y
  if mode == 'play' or mode == 'take' then -- our set play is taken by the one playing the ball only
    x, y = position.target(ctx.role or 'striker', ctx.team_ball, ctx.rules.roles, ctx.world.cfg.field, ctx.clearing)
  end
  if mode == 'play' and not x then
    if ctx.body:state() == 'idle' then ctx.body:event('start', ctx) end
    ctx.body:update(ctx)
  elseif x then -- a role that keeps its position (Player/Team/position.lua)
    if ctx.body:state() ~= 'idle' then ctx.body:event('stop', ctx) end
    moves.go_to(ctx, x, y, ctx.rules.roles.arrive)
  else
    if ctx.body:state() ~= 'idle' then ctx.body:event('stop', ctx) end
    moves[mode](ctx, distance)
  end
  ctx.head:update(ctx)
end

return M
