-- Whether to shoot now with a kick out of the walk (Lib/Walk.lua Walk.kick): the ball in the kick
-- zone ahead of one foot and the goal in front (the kick goes along the robot's heading), the pose
-- trusted, the walk going straight (the kick is made for that). Config body.walk_kick
-- (Config/common/behavior.lua; the body's zone in its behavior.lua).
local nav = require('BodyFSM.nav')
local localize = require('BodyFSM.localize')

local M = {}

-- The kicking foot ('left' or 'right') when a shot is on, else nil.
function M.foot(ctx)
  local cfg = ctx.cfg.body
  local wk = cfg.walk_kick
  if not (wk and wk.enabled) or not ctx.world:ball_known() or localize.needed(ctx) then return nil end
  if ctx.world:ball_age() > wk.max_age then return nil end
  local bx, by, ux, uy, dist = nav.attack(ctx)
  -- (a ball up to x_far further ahead is taken too: the walk waits for a step of the kicking foot
  -- that starts near enough, walk.lua walkKick.<kind>.ballMax, while it walks on at the kick's speed)
  local x_hi = wk.x[2] + (wk.x_far or 0)
  if bx < wk.x[1] or bx > x_hi or math.abs(by) < wk.y[1] or math.abs(by) > wk.y[2] then return nil end
  if dist > wk.max_range then return nil end
  -- the kick is made for walking straight on: not while side-stepping or turning
  local _, vy, va = ctx.act.walk_velocity()
  if math.abs(vy) > wk.max_vy or math.abs(va) > wk.max_va then return nil end
  -- the aim's direction near the heading, and the heading's line from the ball into the goal's
  -- mouth less a margin each side (the right post's end seen to the right of it, the left's to the left)
  if math.abs(nav.wrap(math.atan2(uy, ux))) > wk.max_angle then return nil end
  local f = ctx.world.cfg.field
  local gw = f.goal_width / 2 - wk.margin
  if gw <= 0 then return nil end
  local rx, ry = ctx.world:to_robot(f.length / 2, -gw)
  local lx, ly = ctx.world:to_robot(f.length / 2, gw)
  if not (math.atan2(ry - by, rx - bx) < 0 and math.atan2(ly - by, lx - bx) > 0) then return nil end
  return by > 0 and 'left' or 'right'
end

return M
