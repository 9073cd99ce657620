-- Fine positioning: the ball just ahead of one foot, facing the opponent goal.
local nav = require('BodyFSM.nav')
local localize = require('BodyFSM.localize')
local shot = require('BodyFSM.shot')
local fsm = require('fsm')

local M = {}

-- per activation (ctx): t0 (entry time), good (ticks lined up in a row), side (+1: the left foot kicks)
function M.entry(ctx)
  local d = fsm.fresh(ctx, 'BodyFSM.align')
  d.t0, d.good = ctx.t, 0
  d.side = ctx.world.ball.y >= 0 and 1 or -1
end

function M.update(ctx)
  local cfg = ctx.cfg.body
  local d = fsm.data(ctx, 'BodyFSM.align')
  if not ctx.world:ball_known() then return 'lost' end
  if localize.needed(ctx) then return 'unsure' end
  if nav.ball_in_goal(ctx) then return 'in_goal' end
  local foot = shot.foot(ctx)
  if foot then ctx.kick_side = foot return 'shoot' end
  local bx, by, ux, uy = nav.attack(ctx)
  local dist = math.sqrt(bx * bx + by * by)
  if dist > cfg.align_distance + cfg.align_far then return 'far' end
  -- keep the kicking side unless the ball moved clearly to the other one
  if by * d.side < -cfg.kick_side_switch then d.side = -d.side end
  local dribble = cfg.dribble.enabled
  -- dribbling: the ball centred between the feet; kicking: ahead of the kicking foot
  local ex, ey = bx - cfg.kick_x, by - (dribble and 0 or d.side * cfg.kick_y)
  local ea = nav.wrap(math.atan2(uy, ux))
  -- turn around the ball: sideways motion couples with the turn
  local a = cfg.align
  local vx = nav.clamp(a.gain[1] * ex, a.vx[1], a.vx[2])
  local vy = nav.clamp(a.gain[2] * ey - a.sideways_per_turn * ea, -cfg.max_vy, cfg.max_vy)
  local va = nav.clamp(a.gain[3] * ea, -a.max_va, a.max_va)
  ctx.act.walk(vx, vy, va)
  local ok = math.abs(ex) < cfg.kick_tolerance_x and math.abs(ey) < cfg.kick_tolerance_y
    and math.abs(ea) < cfg.kick_tolerance_angle
  d.good = ok and d.good + 1 or 0
  ctx.kick_side = d.side > 0 and 'left' or 'right'
  if dribble then
    local dr = cfg.dribble
    -- (the ball just seen; lined up further out: dribble on at speed instead of creeping up to it)
    if ctx.world:ball_age() < dr.fresh_age and math.abs(ey) < dr.start_side and math.abs(ea) < dr.start_angle
      and ex > -dr.start_ahead and ex < dr.start_far then
      return 'dribble'
    end
  end
  if d.good >= 3 or ctx.t - d.t0 > cfg.align_timeout then return 'done' end
end

return M
