-- Sweep the head across the field in rows (far, near) until the ball is seen.
local point = require('HeadFSM.point')

local M = {}
local t0

function M.entry(ctx) t0 = ctx.t end

function M.update(ctx)
  local cfg = ctx.cfg.head
  if ctx.world:ball_age() < 0.2 then return 'ball' end
  local s = (ctx.t - t0) / cfg.scan_period
  local sweep = math.floor(s)
  local phase = s - sweep
  -- triangle wave from -1 to 1 and back, direction alternating per sweep
  local u = phase < 0.5 and (4 * phase - 1) or (3 - 4 * phase)
  local rows = cfg.scan_distances
  local dist = rows[(sweep % #rows) + 1]
  local bearing = u * cfg.scan_pan
  local pan, tilt = point.ground(dist * math.cos(bearing), dist * math.sin(bearing), cfg.ground_z)
  ctx.act.head(pan, tilt)
end

return M
