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

local support = require('support_polygon')
local rotate = support.rotate

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
    local corners = support.sole_corners(urdf, link, Config.robot_file(robot.description))
    self.feet_[k] = { link = link, corners = corners, frame = fp and fp[key].frame,
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
  return support.inside(support.hull(pts), zx, zy)
end

return M
