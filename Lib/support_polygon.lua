-- The support polygon of a body's feet, from its URDF: the bottom faces of the collision boxes named
-- sole* on each foot link, their convex hull on the ground, and a point's distance inside it. Used by
-- the teleoperation validator (Lib/teleop.lua) and the whole-body scenarios' ZMP margin
-- (Tests/wbc/zmp_margin.lua).
--   local sp = require('support_polygon')
--   local corners = sp.sole_corners(urdf_text, 'l_foot', file)   -- {x, y, z} in the link's frame
--   local poly = sp.hull(points)                                 -- {x, y} counter-clockwise
--   local d = sp.inside(poly, x, y)                              -- m inside (< 0: outside)
local M = {}

local function nums(s)
  local t = {}
  for x in s:gmatch('[-%d.eE+]+') do t[#t + 1] = tonumber(x) end
  return t
end

-- R = Rz(yaw) Ry(pitch) Rx(roll) applied to v
function M.rotate(rpy, v)
  local cr, sr = math.cos(rpy[1]), math.sin(rpy[1])
  local cp, sp = math.cos(rpy[2]), math.sin(rpy[2])
  local cy, sy = math.cos(rpy[3]), math.sin(rpy[3])
  local x, y, z = v[1], cr * v[2] - sr * v[3], sr * v[2] + cr * v[3]
  x, z = cp * x + sp * z, -sp * x + cp * z
  return { cy * x - sy * y, sy * x + cy * y, z }
end

-- The bottom corners of link `link`'s sole* boxes in the link's frame; `file` names the URDF in errors.
function M.sole_corners(urdf, link, file)
  local body = urdf:match('<link name="' .. link .. '">(.-)</link>')
  if not body then error(string.format('%s: no link %s', file, link), 0) end
  local pts = {}
  local pattern = '<collision name="sole[^"]*">%s*<origin ([^>]*)/>%s*<geometry><box size="([^"]+)"/>'
  for attrs, size in body:gmatch(pattern) do
    local o = nums(attrs:match('xyz="([^"]+)"'))
    local rpy = nums(attrs:match('rpy="([^"]+)"') or '0 0 0')
    local s = nums(size)
    for _, c in ipairs({ { 1, 1 }, { 1, -1 }, { -1, 1 }, { -1, -1 } }) do
      local p = M.rotate(rpy, { c[1] * s[1] / 2, c[2] * s[2] / 2, -s[3] / 2 })
      pts[#pts + 1] = { o[1] + p[1], o[2] + p[2], o[3] + p[3] }
    end
  end
  if #pts == 0 then error(string.format('%s: link %s has no collision box named sole*', file, link), 0) end
  return pts
end

-- Andrew's monotone chain: the convex hull of 2-D points {x, y}, counter-clockwise (sorts `pts`).
function M.hull(pts)
  table.sort(pts, function(a, b) return a[1] < b[1] or (a[1] == b[1] and a[2] < b[2]) end)
  local function cross(o, a, b) return (a[1] - o[1]) * (b[2] - o[2]) - (a[2] - o[2]) * (b[1] - o[1]) end
  local lower, upper = {}, {}
  for _, p in ipairs(pts) do
    while #lower >= 2 and cross(lower[#lower - 1], lower[#lower], p) <= 0 do lower[#lower] = nil end
    lower[#lower + 1] = p
  end
  for i = #pts, 1, -1 do
    local p = pts[i]
    while #upper >= 2 and cross(upper[#upper - 1], upper[#upper], p) <= 0 do upper[#upper] = nil end
    upper[#upper + 1] = p
  end
  lower[#lower], upper[#upper] = nil, nil
  for _, p in ipairs(upper) do lower[#lower + 1] = p end
  return lower
end

-- Signed distance of (x, y) inside a counter-clockwise convex polygon (< 0: outside, by about that).
function M.inside(poly, x, y)
  local d = math.huge
  for i = 1, #poly do
    local a, b = poly[i], poly[i % #poly + 1]
    local ex, ey = b[1] - a[1], b[2] - a[2]
    local len = math.sqrt(ex * ex + ey * ey)
    if len > 0 then d = math.min(d, (ex * (y - a[2]) - ey * (x - a[1])) / len) end
  end
  return d
end

return M
