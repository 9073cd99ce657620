-- The pinhole camera model and the projection between image and ground.
--
--   local project = require('Vision.project')
--   local cm = project.camera(640, 480, math.rad(43.3))     -- square pixels, centred principal point
--   local x, y = project.to_ground(cm, pose, u, v, 0.07)     -- pixel -> point 0.07 m above the ground
--   local u, v = project.to_image(cm, pose, x, y, z)         -- point (z above the ground) -> pixel
-- pose: the camera pose in the level frame from kinematics' camera_pose ({x, y, z, R = {9}, height}):
-- origin at the torso, x forward, y left, z up, torso roll/pitch removed; camera frame x = optical
-- axis, y = image left, z = image up; R maps camera to level coordinates (row-major).
-- The level frame's x/y is the robot frame of the detections. Pixel coordinates are continuous:
-- (0, 0) is the top-left corner of the top-left pixel, u right, v down.
local M = {}

-- A camera of width x height pixels with vertical field of view fovy (rad).
function M.camera(width, height, fovy)
  local f = (height / 2) / math.tan(fovy / 2)
  return { width = width, height = height, f = f, cx = width / 2, cy = height / 2 }
end

-- Direction of the ray through pixel (u, v), level frame (not normalised).
function M.ray(cm, pose, u, v)
  local a, b, c = 1, -(u - cm.cx) / cm.f, -(v - cm.cy) / cm.f
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
  return cm.cx - cm.f * b / a, cm.cy - cm.f * c / a, a
end

return M
