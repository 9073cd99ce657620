-- Walk the ball towards the opponent goal: the ball kept centred just ahead of the feet, the
-- robot turning towards the attack direction and side-stepping to stay behind the ball. Used
-- instead of kicking when the kick moves the ball little (config body.dribble).
local nav = require('BodyFSM.nav')
local localize = require('BodyFSM.localize')
local shot = require('BodyFSM.shot')

local M = {}

function M.update(ctx)
  local cfg = ctx.cfg.body
  local d = cfg.dribble
  if not ctx.world:ball_known() then return 'lost' end
  if localize.needed(ctx) then return 'unsure' end
  local foot = shot.foot(ctx)
  if foot then ctx.kick_side = foot return 'shoot' end
  local bx, by, ux, uy = nav.attack(ctx)
  local ea = nav.wrap(math.atan2(uy, ux))
  -- while the head looks at the goal the ball's estimate stays where it was last seen and the
  -- robot walks up to it (the ball it pushes rolls on): only a fresh sighting says it got away
  local fresh = ctx.world:ball_age() < d.fresh_age
  if not fresh then by = 0 end
  -- the ball got away (ahead, behind or to the side) or the goal is no longer ahead: align again
  if (fresh and (bx > d.max_ahead or bx < d.min_ahead or math.abs(by) > d.max_side)) or math.abs(ea) > d.max_angle then
    return 'realign'
  end
  local slow = math.max(0, 1 - math.abs(ea) / d.max_angle) * math.max(d.slow_min, 1 - math.abs(by) / d.max_side)
  local vx = d.speed * slow
  local vy = nav.clamp(d.side_gain * by - d.side_per_turn * ea, -cfg.max_vy, cfg.max_vy)
  local va = nav.clamp(d.turn_gain * ea, -d.max_va, d.max_va)
  ctx.act.walk(vx, vy, va)
end

return M
