-- The camera model and the projection between image and ground.
--
--   local project = require('Vision.project')
--   local cm = project.from_config(ccfg)                     -- the body's calibration (camera.lua)
--   local cm = project.camera(640, 480, math.rad(43.3))     -- square pixels, centred principal point
--   local x, y = project.to_ground(cm, pose, u, v, 0.07)     -- pixel -> point 0.07 m above the ground
--   local u, v = project.to_image(cm, pose, x, y, z)         -- point (z above the ground) -> pixel
-- pose: the camera pose in the level frame from kinematics' camera_pose ({x, y, z, R = {9}, height}):
-- origin at the torso, x forward, y left, z up, torso roll/pitch removed; camera frame x = optical
-- axis, y = image left, z = image up; R maps camera to level coordinates (row-major).
-- The level frame's x/y is the robot frame of the detections. Pixel coordinates are continuous:
-- (0, 0) is the top-left corner of the top-left pixel, u right, v down.
-- The lens: radial distortion x_d = x (1 + k1 r^2 + k2 r^4) of the pinhole's normalised coordinates
-- (OpenCV's model without the tangential terms); a pixel is undistorted before it is projected, a
-- point distorted after. With k1 = k2 = 0 it is the plain pinhole, with the pinhole's arithmetic.
local M = {}

-- A camera of width x height pixels with vertical field of view fovy (rad); calib (optional, the
-- camera config): intrinsics = { fx, fy, cx, cy } in OpenCV's convention (pixel centres at integer
-- coordinates: its cx is this module's cx - 0.5), distortion = { k1, k2 }.
function M.camera(width, height, fovy, calib)
  local f = (height / 2) / math.tan(fovy / 2)
  local cm = { width = width, height = height, f = f, fx = f, fy = f, cx = width / 2, cy = height / 2, k1 = 0, k2 = 0 }
  local intr, dist = calib and calib.intrinsics, calib and calib.distortion
  if intr then
    cm.fx, cm.fy, cm.cx, cm.cy = intr.fx, intr.fy, intr.cx + 0.5, intr.cy + 0.5
    cm.f = cm.fx
  end
  if dist then cm.k1, cm.k2 = dist.k1, dist.k2 end
  return cm
end

-- The camera of a camera config (Config.load('camera')): its size, field of view and calibration.
function M.from_config(ccfg)
  return M.camera(ccfg.width, ccfg.height, ccfg.fovy, ccfg)
end

-- Pinhole coordinates (x right, y down, at unit depth) of the distorted ones (fixed-point
-- iteration, as OpenCV's undistortPoints).
function M.undistort(cm, xd, yd)
  local k1, k2 = cm.k1, cm.k2
  local x, y = xd, yd
  for _ = 1, 20 do
    local r2 = x * x + y * y
    local k = 1 + r2 * (k1 + r2 * k2)
    local nx, ny = xd / k, yd / k
    local done = math.abs(nx - x) + math.abs(ny - y) < 1e-12
    x, y = nx, ny
    if done then break end
  end
  return x, y
end

-- Direction of the ray through pixel (u, v), level frame (not normalised).
function M.ray(cm, pose, u, v)
  local b, c
  if cm.k1 ~= 0 or cm.k2 ~= 0 then
    local x, y = M.undistort(cm, (u - cm.cx) / cm.fx, (v - cm.cy) / cm.fy)
    b, c = -x, -y
  else
    b, c = -(u - cm.cx) / cm.fx, -(v - cm.cy) / cm.fy
  end
  local a = 1
  local R = pose.R
  return R[1] * a + R[2] * b + R[3] * c, R[4] * a + R[5] * b + R[6] * c, R[7] * a + R[8] * b + R[9] * c
end

-- The point where the ray through (u, v) meets the plane z_above metres above the ground:
-- x, y in the level (robot) frame, or nil if the ray does not go down to it.
function M.to_ground(cm, pose, u, v, z_above)
  local dx, dy, dz = M.ray(cm, pose, u, v)
  local drop = pose.height - (z_above or 0)   -- camera height above the plane
  if dz >= -1e-6 or drop <= 0 then return nil end
  local t = drop / -dz
  return pose[1] + t * dx, pose[2] + t * dy, t * math.sqrt(dx * dx + dy * dy + dz * dz)
end

-- Pixel of the point (x, y) in the level frame at z metres above the ground; nil if behind.
-- Also returns the distance along the optical axis.
function M.to_image(cm, pose, x, y, z)
  local R = pose.R
  -- the ground is pose.height below the camera
  local px, py, pz = x - pose[1], y - pose[2], (z or 0) - pose.height
  -- camera coordinates: R^T * (p - c)
  local a = R[1] * px + R[4] * py + R[7] * pz
  local b = R[2] * px + R[5] * py + R[8] * pz
  local c = R[3] * px + R[6] * py + R[9] * pz
  if a <= 1e-6 then return nil end
  if cm.k1 ~= 0 or cm.k2 ~= 0 then
    local xn, yn = -b / a, -c / a
    local r2 = xn * xn + yn * yn
    local k = 1 + r2 * (cm.k1 + r2 * cm.k2)
    return cm.cx + cm.fx * xn * k, cm.cy + cm.fy * yn * k, a
  end
  return cm.cx - cm.fx * b / a, cm.cy - cm.fy * c / a, a
end

return M
