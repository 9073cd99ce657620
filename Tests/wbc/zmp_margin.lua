-- The measured ZMP of a body standing in the sim and its margin to the edge of the support polygon,
-- for the whole-body scenarios (Tests/wbc/hubo_reach.lua). The ZMP is the centre of pressure of both
-- feet from their sensors: on a body with point pressure sensors under its soles (robot.lua
-- foot_pressure, dcm.sensor.foot_pressure) the sensors' positions weighted by their forces, else
-- the feet's 6-axis force/torque sensors (dcm.sensor.ft: the wrench each foot link exerts on the
-- leg above it, at the ankle joint, in the link's axes); a foot under `min_force` N does not count;
-- put in the field frame by the feet's true poses and onto the ground plane (the soles' height):
-- the same sensor model as Player/Motion/balance.lua, with the feet's poses from the sim's truth. The
-- support polygon: the convex hull of the soles of the feet that carry weight, the bottom faces of the
-- URDF's collision boxes named sole* on each foot link.
--   local zm = require('zmp_margin').new(Sim, shm)
--   zm:feet()                  -- the feet's true poses (again after the feet moved)
--   local m, zx, zy = zm:margin()   -- m: metres inside the polygon (< 0: outside); nil: no foot loaded
local Config = require('Config')

local M = {}
local Z = {}
Z.__index = Z

local function nums(s) local t = {} for x in s:gmatch('[-%d.eE+]+') do t[#t + 1] = tonumber(x) end return t end

-- R = Rz(yaw) Ry(pitch) Rx(roll) applied to v
local function rotate(rpy, v)
  local cr, sr = math.cos(rpy[1]), math.sin(rpy[1])
  local cp, sp = math.cos(rpy[2]), math.sin(rpy[2])
  local cy, sy = math.cos(rpy[3]), math.sin(rpy[3])
  local x, y, z = v[1], cr * v[2] - sr * v[3], sr * v[2] + cr * v[3]
  x, z = cp * x + sp * z, -sp * x + cp * z
  return { cy * x - sy * y, sy * x + cy * y, z }
end

-- The sole boxes' bottom corners of link `link` in its frame.
local function sole_corners(urdf, link)
  local body = assert(urdf:match('<link name="' .. link .. '">(.-)</link>'), 'zmp_margin: no link ' .. link)
  local pts = {}
  local pattern = '<collision name="sole[^"]*">%s*<origin ([^>]*)/>%s*<geometry><box size="([^"]+)"/>'
  for attrs, size in body:gmatch(pattern) do
    local o = nums(attrs:match('xyz="([^"]+)"'))
    local rpy = nums(attrs:match('rpy="([^"]+)"') or '0 0 0')
    local s = nums(size)
    for _, c in ipairs({ { 1, 1 }, { 1, -1 }, { -1, 1 }, { -1, -1 } }) do
      local p = rotate(rpy, { c[1] * s[1] / 2, c[2] * s[2] / 2, -s[3] / 2 })
      pts[#pts + 1] = { o[1] + p[1], o[2] + p[2], o[3] + p[3] }
    end
  end
  assert(#pts > 0, 'zmp_margin: no sole* collision box on ' .. link)
  return pts
end

-- Convex hull (counter-clockwise) of 2-D points {x, y}.
local function hull(pts)
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

function M.new(Sim, shm)
  local robot = Config.load('robot')
  local f = assert(io.open(Config.robot_file(robot.description), 'r'))
  local urdf = f:read('*a')
  f:close()
  local self = setmetatable({ Sim = Sim, sensor = shm.open('dcm.sensor'), feet_ = {},
    min_force = Config.load('walk').balance.minForce }, Z)
  local fp = Config.optional(robot, 'foot_pressure')
  for k, key in ipairs({ 'lfoot', 'rfoot' }) do
    local link
    if fp then
      -- the link the sensors' frame is fixed to
      link = assert(urdf:match('<joint name="[^"]*" type="fixed">%s*<parent link="([^"]+)"/>%s*<child link="'
        .. fp[key].frame .. '"/>'), 'zmp_margin: no link carries the frame ' .. fp[key].frame)
    else
      local joint = robot.ft[key]
      link = assert(urdf:match('<joint name="' .. joint .. '".-<child link="([^"]+)"'),
        'zmp_margin: no child link of ' .. joint)
    end
    self.feet_[k] = { link = link, corners = sole_corners(urdf, link), frame = fp and fp[key].frame,
      points = fp and fp[key].points }
  end
  self.pressure = fp ~= nil
  self:feet()
  return self
end

-- The feet's true poses and their soles' corners on the ground.
function Z:feet()
  local n, zg = 0, 0
  for _, foot in ipairs(self.feet_) do
    local p = self.Sim.link_truth(foot.link)
    foot.pos, foot.rpy, foot.ground = { p.x, p.y, p.z }, { p.roll, p.pitch, p.yaw }, {}
    for k, c in ipairs(foot.corners) do
      local w = rotate(foot.rpy, c)
      foot.ground[k] = { foot.pos[1] + w[1], foot.pos[2] + w[2] }
      zg, n = zg + foot.pos[3] + w[3], n + 1
    end
    if foot.frame then
      -- the pressure sensors on the ground plane
      local s = self.Sim.link_truth(foot.frame)
      foot.sensors = {}
      for k, q in ipairs(foot.points) do
        local w = rotate({ s.roll, s.pitch, s.yaw }, { q[1], q[2], 0 })
        foot.sensors[k] = { s.x + w[1], s.y + w[2] }
      end
    end
  end
  self.ground = zg / n
end

-- The ZMP {x, y} on the ground plane, field frame, from the pressure sensors (nil: no foot loaded).
function Z:pressure_zmp()
  local n = #self.feet_[1].points + #self.feet_[2].points
  local f = self.sensor:read(function(x) local t = {} for i = 1, n do t[i] = x.foot_pressure[i - 1] end return t end)
  local sfz, sx, sy, o = 0, 0, 0, 0
  for _, foot in ipairs(self.feet_) do
    local fz = 0
    for k = 1, #foot.points do fz = fz + f[o + k] end
    foot.loaded = fz > self.min_force
    if foot.loaded then
      for k, p in ipairs(foot.sensors) do
        sx, sy, sfz = sx + f[o + k] * p[1], sy + f[o + k] * p[2], sfz + f[o + k]
      end
    end
    o = o + #foot.points
  end
  if sfz <= 0 then return nil end
  return sx / sfz, sy / sfz
end

-- The measured ZMP {x, y} on the ground plane, field frame (nil: no foot carries weight).
function Z:zmp()
  if self.pressure then return self:pressure_zmp() end
  local ft = self.sensor:read(function(x) local t = {} for i = 1, 12 do t[i] = x.ft[i - 1] end return t end)
  local sfz, sx, sy = 0, 0, 0
  for k, foot in ipairs(self.feet_) do
    local o = 6 * (k - 1)
    foot.loaded = ft[o + 3] > self.min_force
    if foot.loaded then
      local F = rotate(foot.rpy, { ft[o + 1], ft[o + 2], ft[o + 3] })
      local Mo = rotate(foot.rpy, { ft[o + 4], ft[o + 5], ft[o + 6] })
      local a, h = foot.pos, foot.pos[3] - self.ground
      sx = sx + a[1] * F[3] - Mo[2] - h * F[1]
      sy = sy + a[2] * F[3] + Mo[1] - h * F[2]
      sfz = sfz + F[3]
    end
  end
  if sfz <= 0 then return nil end
  return sx / sfz, sy / sfz
end

-- The measured ZMP's distance inside the support polygon (m; negative outside), and the ZMP. The
-- polygon: the convex hull of the soles of the feet that carry weight (one foot while the other
-- swings).
function Z:margin()
  local zx, zy = self:zmp()
  if not zx then return nil end
  return self:margin_of(zx, zy), zx, zy
end

-- The same for the sim's truth (Sim.truth().cop: the centre of pressure of the ground's forces on the
-- soles), in the polygon of the feet the sensors find loaded (call margin() first on the tick): it
-- cannot leave the soles, but it sits on an edge while a foot tips about it, where sensors a little
-- inside the edge (pressure sensors) can show no more than their own edge.
function Z:truth_margin()
  local cop = self.Sim.truth().cop
  if cop.fz <= 0 then return nil end
  return self:margin_of(cop.x, cop.y), cop.x, cop.y
end

-- The distance of (zx, zy) inside the polygon of the loaded feet (m; negative outside).
function Z:margin_of(zx, zy)
  local pts = {}
  for _, foot in ipairs(self.feet_) do
    if foot.loaded then for _, p in ipairs(foot.ground) do pts[#pts + 1] = { p[1], p[2] } end end
  end
  local poly, m = hull(pts), math.huge
  for i = 1, #poly do
    local a, b = poly[i], poly[i % #poly + 1]
    local ex, ey = b[1] - a[1], b[2] - a[2]
    local d = (ex * (zy - a[2]) - ey * (zx - a[1])) / math.sqrt(ex * ex + ey * ey)   -- left of a->b: inside
    m = math.min(m, d)
  end
  return m
end

return M
