-- Walk to the point behind the ball on the line from the opponent goal.
local nav = require('BodyFSM.nav')
local localize = require('BodyFSM.localize')
local shot = require('BodyFSM.shot')

local M = {}

function M.update(ctx)
  local cfg = ctx.cfg.body
  if not ctx.world:ball_known() then return 'lost' end
  if localize.needed(ctx) then return 'unsure' end
  if nav.ball_in_goal(ctx) then return 'in_goal' end
  local foot = shot.foot(ctx)
  if foot then ctx.kick_side = foot return 'shoot' end
  local tx, ty, ha = nav.behind_ball(ctx)
  local vx, vy, va, d = nav.go_to(ctx, tx, ty, ha)
  ctx.act.walk(vx, vy, va)
  if d < cfg.align_distance - cfg.approach_near then return 'near' end
end

return M
