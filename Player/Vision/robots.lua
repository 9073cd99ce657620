-- Other robots on the colour pipeline's label image: what stands on the field and is not field.
--
--   local robots = require('Vision.robots')
--   robots.detect(p, cm, pose, cfg.robots, out)   -- out.n, out[i] = { x, y, range, u0, v0, u1, v1, team }
--
-- Per column (every `column_step` label pixels), from the image's bottom up: the first run of
-- `min_run` pixels that are neither field (green) nor a line or post (white) is something standing
-- on the field; its lowest pixel, with field right under it, is its foot, put on the ground with the
-- camera pose. A column counts when the foot is within `max_range` and the run reaches `min_height`
-- above the ground there (the ball, a shadow or label noise does not). Neighbouring columns whose
-- feet lie within `join` m of each other are one robot, kept if it is `min_width`..`max_width` m
-- wide. Its team: the jersey's colour (label bits `teams`: GameController numbering, 0 blue, 1 red)
-- counted in its box. Up to `max_robots`, nearest first. The world model drops what its pose puts
-- off the field (the floor beyond the carpet's edge looks the same).
local project = require('Vision.project')

local M = {}

local band, floor, sqrt = bit.band, math.floor, math.sqrt
local col_ok, col_x, col_y, col_r, col_top, col_bot = {}, {}, {}, {}, {}, {}
local found = {}

-- the label row (continuous) of the horizon in full-resolution column u, or nil
local function horizon_v(cm, pose, u)
  local R = pose.R
  if math.abs(R[9]) < 1e-3 then return nil end
  local b = -(u - cm.cx) / cm.f
  local c = -(R[7] + R[8] * b) / R[9]
  return cm.cy - cm.f * c
end

-- One column x: the foot and the top of the lowest standing run, or nil.
local function column(L, wa, ha, x, s, cm, pose, cfg, field)
  local u = (x + 0.5) * s
  local hv = horizon_v(cm, pose, u)
  if not hv then return nil end
  local yh = math.max(-1, floor(hv / s)) -- the horizon, or above the image when looking down
  local run, y = 0, ha - 1
  -- up from the bottom to the first `min_run` non-field pixels in a row (below the horizon)
  while y > yh do
    if band(L[y * wa + x], field) == 0 then
      run = run + 1
      if run >= cfg.min_run then break end
    else
      run = 0
    end
    y = y - 1
  end
  if run < cfg.min_run then return nil end
  local yb = y + run - 1
  if yb >= ha - 1 then return nil end -- the foot out of the image: its range is unknown
  -- up the run, bridging `gap` field pixels (legs apart, a line seen between them)
  local yt, miss = y, 0
  y = y - 1
  while y >= 0 and miss <= cfg.gap do
    if band(L[y * wa + x], field) == 0 then yt, miss = y, 0 else miss = miss + 1 end
    y = y - 1
  end
  local gx, gy, r = project.to_ground(cm, pose, u, (yb + 1) * s, 0)
  if not gx or r > cfg.max_range then return nil end
  local _, vt = project.to_image(cm, pose, gx, gy, cfg.min_height)
  if not vt or yt * s > vt then return nil end
  return gx, gy, sqrt(gx * gx + gy * gy), yt, yb
end

-- The team of a box (label x0..x1, y0..y1): the jersey colour with the most pixels, if enough.
local function team_of(p, cfg, x0, x1, y0, y1)
  local best, best_n = -1, cfg.min_team_pixels - 1
  for team, bits in pairs(cfg.teams) do
    local n = p:color_stats(bits, x0, x1, y0, y1).area
    if n > best_n then best, best_n = team, n end
  end
  return best
end

function M.detect(p, cm, pose, cfg, out)
  out.n = 0
  local L, wa, ha, s = p.labels, p.wa, p.ha, p.scale
  local field, step = cfg.field, cfg.column_step
  for x = 0, wa - 1, step do
    local gx, gy, r, yt, yb = column(L, wa, ha, x, s, cm, pose, cfg, field)
    col_ok[x] = gx ~= nil
    if gx then col_x[x], col_y[x], col_r[x], col_top[x], col_bot[x] = gx, gy, r, yt, yb end
  end
  -- neighbouring columns (one missing bridged) with feet close together: one robot
  local nf = 0
  local x = 0
  while x < wa do
    if col_ok[x] then
      local x0, x1, last = x, x, x
      local sx, sy, k, rmin = col_x[x], col_y[x], 1, col_r[x]
      local top, bot = col_top[x], col_bot[x]
      local nx = x + step
      while nx < wa and nx - last <= 2 * step do
        if col_ok[nx] then
          if (col_x[nx] - col_x[last]) ^ 2 + (col_y[nx] - col_y[last]) ^ 2 > cfg.join ^ 2 then break end
          sx, sy, k = sx + col_x[nx], sy + col_y[nx], k + 1
          if col_r[nx] < rmin then rmin = col_r[nx] end
          if col_top[nx] < top then top = col_top[nx] end
          if col_bot[nx] > bot then bot = col_bot[nx] end
          x1, last = nx, nx
        end
        nx = nx + step
      end
      local width = sqrt((col_x[x1] - col_x[x0]) ^ 2 + (col_y[x1] - col_y[x0]) ^ 2)
      -- a robot at the image's side edge is reported too (its width there is a lower bound)
      local at_edge = x0 < step or x1 >= wa - step
      if (width >= cfg.min_width or at_edge) and width <= cfg.max_width then
        nf = nf + 1
        local f = found[nf] or {}
        found[nf] = f
        f.x, f.y, f.range = sx / k, sy / k, rmin
        f.u0, f.v0, f.u1, f.v1 = x0 * s, top * s, (x1 + 1) * s, (bot + 1) * s
        f.team = team_of(p, cfg, x0, x1, top, bot)
      end
      x = x1 + step
    else
      x = x + step
    end
  end
  -- nearest first, at most max_robots
  for i = nf + 1, #found do found[i].range = math.huge end
  table.sort(found, function(a, b) return a.range < b.range end)
  local n = math.min(nf, cfg.max_robots)
  for i = 1, n do out[i] = found[i] end
  out.n = n
  return out
end

return M
