-- Other robots standing on the field, from the label image and the field boundary
-- (Modules/balldetect's obstacles: columns of neither field nor line that rise from a foot on the
-- field to the boundary), with the team colour where their jersey shows.
--
--   local detect_robots = require('Vision.detect_robots')
--   detect_robots.find(bd, p, cm, pose, cfg.robots, ball, out)
--   -- out.n; out[i] = { x, y (m, robot frame, the robot's middle on the ground), range, team (-1 unknown,
--   --   0 blue, 1 red), u0, v0, u1, v1 (px box), foot_visible }; nearest first, at most 4
-- ball: the ball detected in this frame (Vision.detect's result): a band that is the ball (the white
-- one's dark patches against what is beyond the field) is not a robot.
local balldetect = require('balldetect')
local project = require('Vision.project')

local M = {}

-- a band's ground point (the middle of its foot row) and its range; nil above the horizon
local function ground(cm, pose, s, x0, x1, foot)
  local gx, gy = project.to_ground(cm, pose, (x0 + x1 + 1) / 2 * s, (foot + 1) * s, 0)
  if not gx then return nil end
  local hx, hy = gx - pose[1], gy - pose[2]
  return gx, gy, math.sqrt(hx * hx + hy * hy)
end

local bands, merged = {}, {}   -- reused from frame to frame: no garbage per frame

-- the team of a band's colour labels: 1 red, 0 blue, -1 unknown
local function team(cfg, red, blue)
  if red >= cfg.min_team and red > 2 * blue then return 1 end
  if blue >= cfg.min_team and blue > 2 * red then return 0 end
  return -1
end
local function leftmost(a, b) return a.x0 < b.x0 end

-- the band (label columns x0..x1, foot row) is the ball detected: within its width, its foot at its
-- bottom, and not a robot standing behind the ball, whose feet it hides: a ball further below the field
-- boundary than 1.5 radii is joined to it in the band's middle column by mostly (70%) non-field
-- labels only when something stands there (the far lines blurred into strips bridge it sparsely)
local function is_ball(ball, bd, p, cfg, x0, x1, foot)
  if not ball.detected then return false end
  local r, s = ball.radius, p.scale
  if x0 * s < ball.u - 1.2 * r or (x1 + 1) * s > ball.u + 1.2 * r or math.abs((foot + 1) * s - (ball.v + r)) > r then
    return false
  end
  local col = math.floor((x0 + x1) / 2)
  local y0, y1 = math.max(0, bd.top[col] + 1), math.floor((ball.v - r) / s)
  if y1 - y0 + 1 <= math.max(1.5 * r / s, cfg.max_gap + 2) then return true end
  return balldetect.C.bd_column_count(p.labels, p.wa, p.ha, col, y0, y1, cfg.field) < 0.7 * (y1 - y0 + 1)
end

function M.find(bd, p, cm, pose, cfg, ball, out)
  out.n = 0
  local n = bd:obstacles(p.labels, p.wa, p.ha, cfg)
  local s = p.scale
  -- bands left to right; neighbours merge when the gap between them is narrower than
  -- cfg.merge_gap m at the nearer one's range and their feet agree (two legs), or one of them is
  -- no wider than an arm (cfg.arm_width m): a hand reaching below the boundary has a far foot;
  -- never when their colours name different teams (a robot further away seen beside a nearer one)
  local nb = 0
  for i = 0, n - 1 do
    local o = bd.obst[i]
    local _, _, dh = ground(cm, pose, s, o.x0, o.x1, o.foot)
    if dh and not is_ball(ball, bd, p, cfg, o.x0, o.x1, o.foot) then
      nb = nb + 1
      local b = bands[nb] or {}
      bands[nb] = b
      b.x0, b.x1, b.top, b.foot, b.vis, b.red, b.blue, b.dh = o.x0, o.x1, o.top, o.foot, o.foot_visible, o.red,
        o.blue, dh
      b.fx0, b.fx1 = o.fx0, o.fx1
    end
  end
  for i = nb + 1, #bands do bands[i] = nil end
  table.sort(bands, leftmost)
  for i = #merged, 1, -1 do merged[i] = nil end
  for _, b in ipairs(bands) do
    local last = merged[#merged]
    local near = last and math.min(last.dh, b.dh)
    local gap_m = last and (b.x0 - last.x1) * s * near / cm.f
    local arm = last and math.min(last.x1 - last.x0 + 1, b.x1 - b.x0 + 1) * s * near / cm.f <= cfg.arm_width
    local agree = last and math.abs(last.dh - b.dh) <= 0.25 * math.max(last.dh, b.dh) + 0.1
    local t1 = last and team(cfg, last.red, last.blue)
    local t2 = last and team(cfg, b.red, b.blue)
    local teams = last and t1 >= 0 and t2 >= 0 and t1 ~= t2
    if last and gap_m <= cfg.merge_gap and (arm or agree) and not teams then
      last.x1, last.top = b.x1, math.min(last.top, b.top)
      if b.foot > last.foot then last.foot, last.dh, last.vis = b.foot, b.dh, b.vis end
      last.fx0, last.fx1 = math.min(last.fx0, b.fx0), math.max(last.fx1, b.fx1)
      last.red, last.blue = last.red + b.red, last.blue + b.blue
    else
      merged[#merged + 1] = b
    end
  end
  for _, o in ipairs(merged) do
    local gx, gy, dh = ground(cm, pose, s, o.x0, o.x1, o.foot)
    -- a foot within the own body's footprint is the own body (its feet, arms or shoulders at the
    -- image's bottom edge when the head looks down): no other robot stands there
    if gx and gx <= cfg.self_x and math.abs(gy) <= cfg.self_y then gx = nil end
    if gx then
      local hx, hy = gx - pose[1], gy - pose[2]
      -- m, at the foot's range: the band's, or its feet's when the field goes on beyond the image's
      -- top edge above it (a robot cut by that edge shows one leg rising to it, its feet below)
      local x0, x1 = o.x0, o.x1
      if o.top == 0 and bd.top[math.floor((o.x0 + o.x1) / 2)] <= 0 then
        x0, x1 = math.min(x0, o.fx0), math.max(x1, o.fx1)
      end
      local width = (x1 - x0 + 1) * s * dh / cm.f
      -- the foot point is the front of the feet: the robot's middle is further along the ray
      local k = (dh + cfg.depth_offset) / dh
      local x, y = pose[1] + hx * k, pose[2] + hy * k
      local range = math.sqrt(x * x + y * y)
      if range <= cfg.max_range and width >= cfg.min_width_m and width <= cfg.max_width_m and out.n < 4 then
        out.n = out.n + 1
        local r = out[out.n] or {}
        out[out.n] = r
        r.x, r.y, r.range = x, y, range
        -- the runs go on into what is beyond the field above a robot: the box ends a robot's
        -- height above its foot
        r.u0, r.u1, r.v1 = o.x0 * s, (o.x1 + 1) * s, (o.foot + 1) * s
        r.v0 = math.max(o.top * s, r.v1 - cm.f * cfg.height / dh)
        r.foot_visible = o.vis ~= 0
        r.team = team(cfg, o.red, o.blue)
      end
    end
  end
  -- nearest first
  for i = 2, out.n do
    local j = i
    while j > 1 and out[j].range < out[j - 1].range do out[j], out[j - 1] = out[j - 1], out[j]; j = j - 1 end
  end
  return out
end

return M
