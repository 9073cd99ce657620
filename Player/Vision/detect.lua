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
  local green_bit = cfg.green_color
  local tol = cfg.size_tolerance
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

-- Goal posts, from columns of the label image. A post is an upright white cylinder standing on
-- the field that rises above the camera's height, so in its columns one vertical white run
-- crosses the horizon, goes down to a base below the horizon with field (green) under it, and up
-- to a point well above the ground at the base's range; field lines lie flat and never cross the
-- horizon, the crossbar never reaches the ground, and the goal line under a post only extends
-- the run's foot. Neighbouring such columns form a band: one post if the band's width agrees with
-- the post diameter at the range of its base (the ground projection of the base's lower edge).
-- Bands touching the image's left or right edge are not reported (position and width unknown).
-- Up to two posts, nearest the image centre first; out.n, out[i] = { u, v, x, y, range, width }.
-- cfg: color, green, diameter, min_rise (m above the ground the run's top must reach, or leave
-- the image at the top), min_rows (label rows of the run), gap (non-white label pixels bridged
-- inside a run, never field), width_tolerance {low, high} (factor on the expected width), max_range (m).
local col_top, col_bot, col_ok = {}, {}, {}

-- the label row (continuous) of the horizon in full-resolution column u, or nil (the pinhole's:
-- a webcam lens bends it by a few pixels at most, within the posts' tolerances)
local function horizon_v(cm, pose, u)
  local R = pose.R
  if math.abs(R[9]) < 1e-3 then return nil end
  local b = -(u - cm.cx) / cm.fx
  local c = -(R[7] + R[8] * b) / R[9]
  return cm.cy - cm.fy * c
end

function M.goal_posts(p, cm, pose, cfg, out)
  out.n = 0
  local L, wa, ha, s = p.labels, p.wa, p.ha, p.scale
  local white, green = cfg.color, cfg.green
  local gap, min_rows = cfg.gap, cfg.min_rows
  local band = bit.band
  -- 1. columns with a white run through the horizon, its base on the field
  for x = 0, wa - 1 do
    col_ok[x] = false
    local u = (x + 0.5) * s
    local hv = horizon_v(cm, pose, u)
    if hv then
      local yh = math.floor(hv / s)
      -- seed: a white pixel on the horizon row or next to it (noise)
      local seed
      for dy = 0, 1 do
        for sg = -1, 1, 2 do
          local y = yh + sg * dy
          if not seed and y >= 0 and y < ha and band(L[y * wa + x], white) ~= 0 then seed = y end
        end
      end
      if seed then
        -- extend the run down and up, bridging up to `gap` non-white pixels
        -- (never across field: a line just beyond the post's foot is not part of it)
        local yb, y, miss = seed, seed + 1, 0
        while y < ha and miss <= gap do
          local l = L[y * wa + x]
          if band(l, white) ~= 0 then yb, miss = y, 0
          elseif band(l, green) ~= 0 then break
          else miss = miss + 1 end
          y = y + 1
        end
        local yt
        yt, y, miss = seed, seed - 1, 0
        while y >= 0 and miss <= gap do
          if band(L[y * wa + x], white) ~= 0 then yt, miss = y, 0 else miss = miss + 1 end
          y = y - 1
        end
        -- base inside the image and below the horizon, field right under it
        if yb - yt + 1 >= min_rows and yb < ha - 1 and yb + 1 > hv / s then
          local on_field = false
          for yy = yb + 1, math.min(ha - 1, yb + 3) do
            if band(L[yy * wa + x], green) ~= 0 then on_field = true end
          end
          if on_field then
            col_ok[x], col_top[x], col_bot[x] = true, yt, yb
          end
        end
      end
    end
  end
  -- 2. bands of such columns (one column's gap bridged), each checked as a post
  local max_range, dia = cfg.max_range, cfg.diameter
  local wtol = cfg.width_tolerance
  local min_rise = cfg.min_rise
  local x = 0
  while x < wa do
    if col_ok[x] then
      local x0, x1 = x, x
      while x1 + 1 < wa and (col_ok[x1 + 1] or (x1 + 2 < wa and col_ok[x1 + 2])) do
        x1 = col_ok[x1 + 1] and x1 + 1 or x1 + 2
      end
      x = x1 + 1
      if x0 == 0 or x1 == wa - 1 then
        refuse('post at the image edge', x0, x1)
      else
        -- the base: median of the columns' lowest white rows; the top: highest row
        local bots, top = {}, ha
        for c = x0, x1 do
          if col_ok[c] then bots[#bots + 1] = col_bot[c]; top = math.min(top, col_top[c]) end
        end
        table.sort(bots)
        local yb = bots[math.floor((#bots + 1) / 2)]
        local u = (x0 + x1 + 1) / 2 * s
        local v = (yb + 1) * s
        local gx, gy = project.to_ground(cm, pose, u, v, 0)
        if not gx then
          refuse('post base above the horizon', v)
        else
          local hx, hy = gx - pose[1], gy - pose[2]
          local dh = math.sqrt(hx * hx + hy * hy)    -- camera to the post's front, horizontally
          -- the post's axis is a radius further along the ray
          local k = (dh + dia / 2) / dh
          local px, py = pose[1] + hx * k, pose[2] + hy * k
          local range = math.sqrt(px * px + py * py)
          -- how high the run's top is at the post (from the camera's height and the top's ray)
          local rx, ry, rz = project.ray(cm, pose, u, top * s)
          local rise = pose.height + rz * (dh / math.sqrt(rx * rx + ry * ry))
          local width = (x1 - x0 + 1) * s
          local expect = cm.f * dia / (dh + dia / 2)
          if range > max_range then
            refuse('post range', range)
          elseif rise < min_rise and top > 0 then
            refuse('post rise', rise)
          elseif width < wtol[1] * expect - s or width > wtol[2] * expect + 2 * s then
            refuse('post width: px, expected', width, expect)
          else
            out.n = out.n + 1
            local post = out[out.n] or {}
            post.u, post.v, post.x, post.y = u, v, px, py
            post.range, post.width = range, width
            out[out.n] = post
          end
        end
      end
    else
      x = x + 1
    end
  end
  -- at most two: nearest the image centre first
  if out.n > 2 then
    local cx = cm.cx
    local list = {}
    for i = 1, out.n do list[i] = out[i] end
    table.sort(list, function(a, b) return math.abs(a.u - cx) < math.abs(b.u - cx) end)
    for i = 1, out.n do out[i] = list[i] end
    out.n = 2
  end
  return out
end

return M
