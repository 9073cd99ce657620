-- The white ball (FIFA size 1, mostly white with a pattern): spots inside the field boundary that
-- are not field, as large as a ball at the range the ground projection gives, checked by a small
-- classifier on the frame's pixels (Modules/balldetect; the model trained by Tools/ball_train).
--
--   local detect_white = require('Vision.detect_white')
--   detect_white.ball(bd, mlp, p, cm, pose, frame, cfg.ball, out)
--   -- out.detected, out.u, out.v, out.radius (px), out.x, out.y, out.range (m), out.score (0..1)
-- bd: a balldetect workspace whose boundary and view are set for this frame; p: the imageproc
-- pipeline that processed it; cm/pose: Vision.project's camera and the camera pose at the frame.
local project = require('Vision.project')

local M = {}

-- Why the last frame had no ball (from the REPL): why, and two figures.
M.reject = { why = '', a = 0, b = 0 }
local reject = M.reject
local function refuse(why, a, b) reject.why, reject.a, reject.b = why, a or 0, b or 0 end

function M.ball(bd, mlp, p, cm, pose, frame, cfg, out)
  out.detected = false
  local w = cfg.white
  local radius = cfg.diameter / 2
  local n = bd:candidates(p.labels, p.wa, p.ha, p.scale, w.green, radius, w)
  bd.ncand = n
  if n == 0 then refuse('no candidate'); return out end
  local best, best_p = nil, w.threshold
  local top_p = 0
  for i = 0, n - 1 do
    local c = bd.cand[i]
    local pr = bd:classify(mlp, frame.yuyv, frame.width, frame.height, c)
    if pr > top_p then top_p = pr end
    if pr >= best_p then best, best_p = c, pr end
  end
  if not best then refuse('classifier: candidates, best probability', n, top_p); return out end
  -- its centre settled (a near ball's is still off after the candidates' two centroid passes), then
  -- from its outline: the centroid takes in a line touching the ball, the outline leaves it out
  local u0, v0 = best.u, best.v
  bd:settle(p.labels, p.wa, p.ha, p.scale, w.green, radius, best)
  bd:fit(p.labels, p.wa, p.ha, p.scale, w.green, radius, u0, v0, best)
  local x, y, dist = project.to_ground(cm, pose, best.u, best.v, radius)
  if not x then refuse('above the horizon', best.v); return out end
  if dist > cfg.max_range then refuse('range', dist); return out end
  out.detected = true
  out.u, out.v, out.radius = best.u, best.v, best.radius
  out.x, out.y, out.range = x, y, dist
  out.score = best_p
  return out
end

return M
