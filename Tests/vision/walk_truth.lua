-- The truth of a walking robot's camera frame for the walking-vision scorer (walk_eye.lua): the
-- camera's true pose from the sim's torso pose and the joint angles at the exposure, whether the
-- ball's whole disc shows in the frame, whether the robot's own arms or legs may hide it, and the
-- camera poses the vision could use (Vision.project's level-frame poses).
--
--   local wt = require('Tests.vision.walk_truth').new(model, cm, robot)
--   local cam = wt:camera(truth, q)            -- world pose { pos = {3}, R = {9} } at the exposure
--   local view = wt:ball_view(cam, ball, r)    -- 'in', 'out' (no part in the frame) or 'partly'
--   local hidden = wt:own_body_hides(truth, q, cam, ball, r)
--   local pose = walk_truth.level_pose(truth, cam)     -- the true camera pose in the robot's level frame
-- truth: the sim block's torso pose { x, y, z, yaw, roll, pitch } (the URDF root link's frame,
-- field frame); q: the joint angles (1-based, robot order); ball: { x, y, z } field frame.
local project = require('Vision.project')

local M = {}
local W = {}
W.__index = W

local sin, cos, sqrt = math.sin, math.cos, math.sqrt

-- R = Rz(yaw) Ry(pitch) Rx(roll), row-major
local function rpy_rot(roll, pitch, yaw)
  local cr, sr, cp, sp, cy, sy = cos(roll), sin(roll), cos(pitch), sin(pitch), cos(yaw), sin(yaw)
  return { cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr,
           sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr,
           -sp, cp * sr, cp * cr }
end
local function mul(A, B)
  local C = {}
  for i = 0, 2 do
    for j = 0, 2 do
      C[3 * i + j + 1] = A[3 * i + 1] * B[j + 1] + A[3 * i + 2] * B[j + 4] + A[3 * i + 3] * B[j + 7]
    end
  end
  return C
end
local function apply(R, x, y, z)
  return R[1] * x + R[2] * y + R[3] * z, R[4] * x + R[5] * y + R[6] * z, R[7] * x + R[8] * y + R[9] * z
end
M.rpy_rot = rpy_rot

-- model: kinematics.load(); cm: Vision.project's camera; robot: Config.load('robot')
function M.new(model, cm, robot)
  local self = setmetatable({ model = model, cm = cm, head = {}, chains = {} }, W)
  local index = {}
  for i, n in ipairs(robot.joints) do index[n] = i end
  for k, n in ipairs(robot.groups.head) do self.head[k] = index[n] end
  -- the limbs as chains of joint indices, for the own-body check
  for _, g in ipairs({ 'larm', 'rarm', 'lleg', 'rleg' }) do
    local c = {}
    for _, n in ipairs(robot.groups[g] or {}) do c[#c + 1] = index[n] end
    self.chains[g] = c
  end
  -- the pinhole radius of the frame's corners: beyond it the lens polynomial folds back
  local r2max = 0
  for k = 0, 3 do
    local u, v = (k % 2 == 1) and cm.width or 0, (k >= 2) and cm.height or 0
    local x, y = project.undistort(cm, (u - cm.cx) / cm.fx, (v - cm.cy) / cm.fy)
    r2max = math.max(r2max, x * x + y * y)
  end
  self.r2max = r2max
  return self
end

-- The camera's pose in the field frame: the torso's true pose times the head chain's forward
-- kinematics at the joint angles q.
function W:camera(t, q)
  local c = self.model:head_fk({ q[self.head[1]], q[self.head[2]] }, nil, q)
  local Rt = rpy_rot(t.roll, t.pitch, t.yaw)
  local x, y, z = apply(Rt, c[1], c[2], c[3])
  return { pos = { t.x + x, t.y + y, t.z + z }, R = mul(Rt, c.R), Rt = Rt }
end

-- Pixel of a field-frame point seen by the camera `cam`, nil when it is behind the camera or
-- beyond the lens's corners (where the distortion polynomial folds far points into the frame).
function W:pixel(cam, x, y, z)
  local R, p = cam.R, cam.pos
  local dx, dy, dz = x - p[1], y - p[2], z - p[3]
  local a = R[1] * dx + R[4] * dy + R[7] * dz
  local b = R[2] * dx + R[5] * dy + R[8] * dz
  local c = R[3] * dx + R[6] * dy + R[9] * dz
  if a <= 1e-6 then return nil end
  local xn, yn = -b / a, -c / a
  if xn * xn + yn * yn > self.r2max then return nil end
  local cm = self.cm
  local k = 1 + (xn * xn + yn * yn) * (cm.k1 + (xn * xn + yn * yn) * cm.k2)
  return cm.cx + cm.fx * xn * k, cm.cy + cm.fy * yn * k
end

-- The ball's outline as the camera sees it: n points of the circle where the cone from the
-- camera's centre touches the sphere (its silhouette), field frame.
local function outline(cam, b, r, n)
  local p = cam.pos
  local dx, dy, dz = b[1] - p[1], b[2] - p[2], b[3] - p[3]
  local d = sqrt(dx * dx + dy * dy + dz * dz)
  if d <= r then return nil end
  local nx, ny, nz = dx / d, dy / d, dz / d
  -- two unit vectors across the line of sight
  local ax, ay, az = -ny, nx, 0
  local al = sqrt(ax * ax + ay * ay)
  if al < 1e-9 then ax, ay, az, al = 1, 0, 0, 1 end
  ax, ay, az = ax / al, ay / al, az / al
  local bx, by, bz = ny * az - nz * ay, nz * ax - nx * az, nx * ay - ny * ax
  local back = r * r / d                 -- the touching circle lies this much nearer than the centre
  local rad = r * sqrt(d * d - r * r) / d
  local cx, cy, cz = b[1] - back * nx, b[2] - back * ny, b[3] - back * nz
  local pts = {}
  for k = 1, n do
    local t = 2 * math.pi * k / n
    local ct, st = cos(t) * rad, sin(t) * rad
    pts[k] = { cx + ct * ax + st * bx, cy + ct * ay + st * by, cz + ct * az + st * bz }
  end
  return pts
end

-- 'in': the ball's whole outline (24 points) projects inside the frame; 'out': none of it, nor its
-- centre (the ball cannot show); 'partly' otherwise.
function W:ball_view(cam, b, r)
  local pts = outline(cam, b, r, 24)
  if not pts then return 'partly' end
  local inside, outside = 0, 0
  local w, h = self.cm.width, self.cm.height
  for _, pt in ipairs(pts) do
    local u, v = self:pixel(cam, pt[1], pt[2], pt[3])
    if u and u >= 0 and v >= 0 and u <= w and v <= h then inside = inside + 1 else outside = outside + 1 end
  end
  if outside == 0 then return 'in' end
  -- a ball whose outline is all outside may still fill the frame (very near): the centre decides
  local u, v = self:pixel(cam, b[1], b[2], b[3])
  if inside == 0 and not (u and u >= 0 and v >= 0 and u <= w and v <= h) then return 'out' end
  return 'partly'
end

-- distance from point p to the segment a-b (3-vectors as tables)
local function seg_point(a, b, p)
  local ux, uy, uz = b[1] - a[1], b[2] - a[2], b[3] - a[3]
  local wx, wy, wz = p[1] - a[1], p[2] - a[2], p[3] - a[3]
  local uu = ux * ux + uy * uy + uz * uz
  local t = uu > 0 and math.max(0, math.min(1, (wx * ux + wy * uy + wz * uz) / uu)) or 0
  local ex, ey, ez = wx - t * ux, wy - t * uy, wz - t * uz
  return sqrt(ex * ex + ey * ey + ez * ez)
end
-- closest distance between segments p1-q1 and p2-q2 (sampled along the first: enough here)
local function seg_seg(p1, q1, p2, q2)
  local best = math.huge
  for k = 0, 20 do
    local t = k / 20
    local x = { p1[1] + t * (q1[1] - p1[1]), p1[2] + t * (q1[2] - p1[2]), p1[3] + t * (q1[3] - p1[3]) }
    best = math.min(best, seg_point(p2, q2, x))
  end
  return best
end

-- LIMB: the radius of a capsule round each limb segment (joint to joint, the last to the hand or
-- sole): the OP3's arm links are ~4 cm across, its leg links ~6 cm; 5 cm covers both with the
-- hands' and feet's extent. True when a line of sight from the camera to the ball's centre or its
-- outline passes within LIMB of a limb: the ball may be partly hidden, the frame is not scored.
local LIMB = 0.05
function W:own_body_hides(t, q, cam, b, r)
  local links = self.model:link_poses(q)
  local Rt = cam.Rt
  local function world(p)
    local x, y, z = apply(Rt, p[1], p[2], p[3])
    return { t.x + x, t.y + y, t.z + z }
  end
  local sights = outline(cam, b, r, 8) or {}
  sights[#sights + 1] = b
  for name, chain in pairs(self.chains) do
    local pts = {}
    for _, j in ipairs(chain) do pts[#pts + 1] = world(links[j]) end
    -- the chain's tip: the hand or the sole
    local side = name:sub(1, 1)
    local qn = {}
    for k, j in ipairs(chain) do qn[k] = q[j] end
    local tip
    if name:find('arm') then tip = self.model:arm_fk(side, qn, nil, q)
    else tip = self.model:leg_fk(side, qn, nil, q) end
    pts[#pts + 1] = world(tip)
    for k = 1, #pts - 1 do
      for _, s in ipairs(sights) do
        if seg_seg(cam.pos, s, pts[k], pts[k + 1]) < LIMB then return true end
      end
    end
  end
  return false
end

-- The true camera pose as Vision.project's pose: level frame (torso origin, heading x, gravity z),
-- height above the ground (z = 0).
function M.level_pose(t, cam)
  local Ry = rpy_rot(0, 0, -t.yaw)
  local p = cam.pos
  local x, y = apply(Ry, p[1] - t.x, p[2] - t.y, 0)
  return { x, y, p[3] - t.z, R = mul(Ry, cam.R), height = p[3] }
end

return M
