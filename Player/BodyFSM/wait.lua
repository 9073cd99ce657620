-- The ball is in a goal (scored, BodyFSM/nav.lua ball_in_goal): stand where the robot is rather than follow
-- it into the net, until the game restarts (the GameController's READY) or the ball is out again.
local nav = require('BodyFSM.nav')

local M = {}

function M.entry(ctx) ctx.act.stop() end

function M.update(ctx)
  if not ctx.world:ball_known() then return 'lost' end
  if not nav.ball_in_goal(ctx) then return 'out' end
  ctx.act.stop()
end

return M
