-- The ball is in a goal (scored, BodyFSM/nav.lua ball_in_goal): stand where the robot is rather than follow
-- it into the net, until the game restarts (the GameController's READY) or the ball is out again; after
-- body.ball_in_goal.wait s play on (the pose may be wrong: a mirrored one puts the ball in the own goal).
local nav = require('BodyFSM.nav')
local fsm = require('fsm')

local M = {}

-- per activation (ctx): t0 (entry time)
function M.entry(ctx)
  fsm.fresh(ctx, 'BodyFSM.wait').t0 = ctx.t
  ctx.act.stop()
end

function M.update(ctx)
  if not ctx.world:ball_known() then return 'lost' end
  if not nav.ball_in_goal(ctx) then return 'out' end
  if ctx.t - fsm.data(ctx, 'BodyFSM.wait').t0 > ctx.cfg.body.ball_in_goal.wait then
    ctx.in_goal_gave_up = ctx.t
    return 'out'
  end
  ctx.act.stop()
end

return M
