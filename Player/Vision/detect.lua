-- Ball and goal-post detection on the colour pipeline's label and block images.
--
--   local detect = require('Vision.detect')
--   detect.ball(p, cm, pose, cfg.ball, out)        -- out.detected, out.u, out.v, out.x, out.y, ...
--   detect.goal_posts(p, cm, pose, cfg.goal, out)  -- out.n, out[i] = { u, v, x, y }
-- p: an imageproc pipeline that has processed the frame; cm/pose: Vision.project's camera model
-- and the camera pose (level frame) at the frame's exposure. Positions are in the robot frame
-- (x forward, y left, metres), image positions in full-resolution pixels.
local project = require('Vision.project')

local M = {}

local GREEN = 8

local function opt(t, k, default)
  local v = rawget(t, k)
  if v == nil then return default end
  return v
end

-- Why the last candidate was refused (for debugging from the REPL): why, and two figures.
M.reject = { why = '', a = 0, b = 0 }
local reject = M.reject
local function refuse(why, a, b) reject.why, reject.a, reject.b = why, a or 0, b or 0 end

-- The ball: the largest ball-coloured region that is round enough, filled enough, has green
-- below it (unless it touches the image's bottom), and whose size agrees with its range.
function M.ball(p, cm, pose, cfg, out)
  out.detected = false
  local s = p.scale
  local n, regs = p:regions(cfg.color, 4)
  local green_bit = opt(cfg, 'green_color', GREEN)
  local tol = opt(cfg, 'size_tolerance', 2.0)
  local radius = cfg.diameter / 2
  for i = 0, math.min(n, 4) - 1 do
    local r = regs[i]
    if r.area < cfg.min_area then refuse('area', r.area); break end
    local bw, bh = r.xmax - r.xmin + 1, r.ymax - r.ymin + 1
    local fill = r.area / (bw * bh)
    local aspect = math.max(bw, bh) / math.min(bw, bh)
    local edge = r.xmin == 0 or r.ymin == 0 or r.xmax == p.wa - 1 or r.ymax == p.ha - 1
    local ok = fill >= cfg.min_fill and aspect <= cfg.max_aspect
    if not ok then refuse('shape: fill, aspect', fill, aspect) end
    -- green in a band below the ball as wide as the ball, half its height (if inside the image)
    if ok and cfg.green_below > 0 and r.ymax + 1 < p.ha then
      local y0, y1 = r.ymax + 1, math.min(p.ha - 1, r.ymax + math.max(2, math.floor(bh / 2)))
      local st = p:color_stats(green_bit, r.xmin, r.xmax, y0, y1)
      local frac = st.area / (bw * (y1 - y0 + 1))
      if frac < cfg.green_below then
        ok = false
        refuse('green below', frac)
      end
    end
    if ok then
      -- centre and apparent diameter in full-resolution pixels
      local u, v = (r.cx + 0.5) * s, (r.cy + 0.5) * s
      local dpx
      if edge then
        dpx = math.max(bw, bh) * s   -- partly outside: the longer side is the best guess
      else
        dpx = 2 * math.sqrt(r.area / math.pi) * s
      end
      local range_size = cm.f * cfg.diameter / dpx
      local x, y, dist = project.to_ground(cm, pose, u, v, radius)
      if x and not edge then
        local ratio = range_size / dist
        if ratio > tol or ratio < 1 / tol then
          ok = false
          refuse('range from size vs ground', range_size, dist)
        end
      elseif not x then
        -- above the horizon of the ball's centre plane: place it along the ray at the size range
        local dx, dy, dz = project.ray(cm, pose, u, v)
        local norm = math.sqrt(dx * dx + dy * dy + dz * dz)
        x, y = pose[1] + dx / norm * range_size, pose[2] + dy / norm * range_size
        dist = range_size
      end
      if ok and dist > cfg.max_range then
        ok = false
        refuse('range', dist)
      end
      if ok then
        out.detected = true
        out.u, out.v, out.radius = u, v, dpx / 2
        out.x, out.y, out.range = x, y, dist
        out.area = r.area
        return out
      end
    end
  end
  return out
end

-- Goal posts: tall, thin, upright regions of the goal colour in the block image that rise above
-- the horizon (or leave the image at the top) with green at their foot. Up to two, largest first.
function M.goal_posts(p, cm, pose, cfg, out)
  out.n = 0
  local unit = p.scale * p.block   -- full-resolution pixels per block
  local n, regs = p:regions(cfg.color, 6, true)
  for i = 0, math.min(n, 6) - 1 do
    local r = regs[i]
    local bh, bw = r.ymax - r.ymin + 1, r.xmax - r.xmin + 1
    if bh >= cfg.min_height and bh >= cfg.min_ratio * bw and r.ymax < p.hb - 1 then
      local top_dz = select(3, project.ray(cm, pose, (r.cx + 0.5) * unit, r.ymin * unit))
      local rises = top_dz > 0 or r.ymin == 0
      -- green at the foot (block image row below)
      local st = p:color_stats(GREEN, r.xmin - 1, r.xmax + 1, r.ymax + 1, r.ymax + 1, true)
      if rises and st.area > 0 then
        local u, v = (r.cx + 0.5) * unit, (r.ymax + 1) * unit
        local x, y = project.to_ground(cm, pose, u, v, 0)
        if x then
          out.n = out.n + 1
          local post = out[out.n] or {}
          post.u, post.v, post.x, post.y = u, v, x, y
          out[out.n] = post
          if out.n == 2 then break end
        end
      end
    end
  end
  return out
end

return M
