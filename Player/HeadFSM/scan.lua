-- Look for the ball: where it was last estimated first, when that is near (a ball at the feet is
-- below the scan's rows), then sweep the head across the field in rows (far, near).
local point = require('HeadFSM.point')
local fsm = require('fsm')

local M = {}

-- per activation (ctx): t0 (the look around the estimate's start), t_rows (the rows' start)
function M.entry(ctx)
  local d = fsm.fresh(ctx, 'HeadFSM.scan')
  d.t0 = ctx.t
  local w, cfg = ctx.world, ctx.cfg.head
  local b = w.ball
  local near = b.seen and w:ball_known() and b.x * b.x + b.y * b.y < cfg.scan_near_first ^ 2
  d.t_rows = near and d.t0 + cfg.scan_near_time or d.t0
end

function M.update(ctx)
  local cfg = ctx.cfg.head
  local w = ctx.world
  local d = fsm.data(ctx, 'HeadFSM.scan')
  if w:ball_age() < 0.2 then return 'ball' end
  -- the body stands to look (BodyFSM/search.lua): a sweep from the start, on the far row first
  if ctx.scan_restart and ctx.scan_restart > d.t_rows then d.t0, d.t_rows = ctx.scan_restart, ctx.scan_restart end
  local t0, t_rows = d.t0, d.t_rows
  local pan, tilt
  if ctx.t < t_rows then
    -- around the estimate, swinging +-scan_swing
    local b = w.ball
    local swing = cfg.scan_swing * math.sin(2 * math.pi * (ctx.t - t0) / cfg.scan_near_time)
    local c, s = math.cos(swing), math.sin(swing)
    pan, tilt = point.ground(c * b.x - s * b.y, s * b.x + c * b.y, cfg)
  else
    local s = (ctx.t - t_rows) / cfg.scan_period
    local sweep = math.floor(s)
    local phase = s - sweep
    -- triangle wave from -1 to 1 and back, direction alternating per sweep
    local u = phase < 0.5 and (4 * phase - 1) or (3 - 4 * phase)
    local rows = cfg.scan_distances
    local dist = rows[(sweep % #rows) + 1]
    local bearing = u * cfg.scan_pan
    if ctx.body_turning and cfg.turning_row_time > 0 then
      -- the body turning on the spot to search sweeps the view round itself: the head looks ahead
      -- and switches rows often (sweeping, a ball the body turned past while the other row was on
      -- went by unseen)
      dist = rows[math.floor((ctx.t - t_rows) / cfg.turning_row_time) % #rows + 1]
      bearing = 0
    end
    pan, tilt = point.ground(dist * math.cos(bearing), dist * math.sin(bearing), cfg)
  end
  ctx.act.head(pan, tilt)
end

return M
