-- Walk the ball towards the opponent goal: the ball kept centred just ahead of the feet, the
-- robot turning towards the attack direction (round a robot in the way: M.detour) and
-- side-stepping to stay behind the ball. Used
-- instead of kicking when the kick moves the ball little (config body.dribble).
local nav = require('BodyFSM.nav')
local localize = require('BodyFSM.localize')
local shot = require('BodyFSM.shot')

local M = {}

-- The aim's turn (rad, + left) that passes a robot standing in the lane ahead of the ball (bx, by;
-- attack direction ux, uy; robot frame), on the side away from it, kept (ctx.dribble_side) while one is there.
function M.detour(ctx, bx, by, ux, uy)
  local d = ctx.cfg.body.dribble
  local best, best_along, best_across
  for _, o in ipairs(nav.robots(ctx) or {}) do
    local ox, oy = o.x - bx, o.y - by
    local along, across = ox * ux + oy * uy, -ox * uy + oy * ux
    if along > 0 and along < d.avoid_ahead and math.abs(across) < d.avoid_lane
      and (not best or along < best_along) then
      best, best_along, best_across = o, along, across
    end
  end
  if not best then ctx.dribble_side = nil return 0 end
  local side = ctx.dribble_side or (best_across > 0 and -1 or 1)
  ctx.dribble_side = side
  -- the aim passes the robot by the lane: the angle from the ball to the point `lane` beside it
  local need = math.atan2(d.avoid_lane + side * best_across, best_along)
  return side * math.min(math.max(need, 0), d.avoid_angle)
end

function M.exit(ctx) ctx.ball_hint = nil end

function M.update(ctx)
  local cfg = ctx.cfg.body
  local d = cfg.dribble
  if not ctx.world:ball_known() then return 'lost' end
  if localize.needed(ctx) then return 'unsure' end
  if nav.ball_in_goal(ctx) then return 'in_goal' end
  local foot = shot.foot(ctx)
  if foot then ctx.kick_side = foot return 'shoot' end
  local bx, by, ux, uy = nav.attack(ctx)
  local ea = nav.wrap(math.atan2(uy, ux) + M.detour(ctx, bx, by, ux, uy))
  -- while the head looks at the goal the ball's estimate stays where it was last seen and the
  -- robot walks up to it (the ball it pushes rolls on): only a fresh sighting says it got away
  local age = ctx.world:ball_age()
  local fresh = age < d.fresh_age
  if not fresh then by = 0 end
  -- ... and the head, back from the goal, looks for it there (HeadFSM/track.lua), not where the
  -- stale estimate has fallen behind to as the robot walked on
  ctx.ball_hint = (not fresh) and { d.hint_ahead, 0 } or nil
  -- not seen there either for a while: it got away, and walking on blind would pass it
  if age > d.stale_age then return 'realign' end
  -- the ball got away (ahead, behind or to the side) or the goal is no longer ahead: align again
  if (fresh and (bx > d.max_ahead or bx < d.min_ahead or math.abs(by) > d.max_side)) or math.abs(ea) > d.max_angle then
    return 'realign'
  end
  -- slower for a ball off to the side or the goal off to the side, beyond the dead bands (the
  -- estimate's jitter and the push's sway alone would keep the walk slow)
  local off_a = math.max(0, math.abs(ea) - d.slow_angle) / (d.max_angle - d.slow_angle)
  local off_y = math.max(0, math.abs(by) - d.slow_side) / (d.max_side - d.slow_side)
  local slow = math.max(0, 1 - off_a) * math.max(d.slow_min, 1 - off_y)
  local vx = d.speed * slow
  local vy = nav.clamp(d.side_gain * by - d.side_per_turn * ea, -cfg.max_vy, cfg.max_vy)
  -- turning a little towards a ball off to the side walks it back in front of the feet (side-stepping
  -- alone is slow)
  local va = nav.clamp(d.turn_gain * ea + d.ball_turn_gain * math.atan2(by, math.max(bx, 0.1)),
    -d.max_va, d.max_va)
  ctx.act.walk(vx, vy, va)
end

return M
