-- The OP3's head camera (Logitech C920) at 640 x 480: vertical field of view and the calibration.
-- The calibration is robot data: the sim renders through it and the vision projects pixels to the
-- ground through it (Player/Vision/project.lua). A robot's own calibration (OpenCV's
-- calibrateCamera at 640 x 480) replaces these numbers, in its site folder if it differs per robot.
local fovy = math.rad(43.3)
local f = 240 / math.tan(fovy / 2)   -- px: the pinhole of fovy over 480 rows (604.6)
return {
  fovy = fovy,                  -- rad
  -- OpenCV's convention: pixel centres at integer coordinates, so the image centre is (319.5, 239.5)
  intrinsics = { fx = f, fy = f, cx = 319.5, cy = 239.5 },
  -- radial distortion, x_d = x (1 + k1 r^2 + k2 r^4) on the pinhole's normalised coordinates. No
  -- published C920 calibration in the robot data: numbers of the order of public 640 x 480 USB webcam
  -- calibrations (ROS plumb_bob files show k1 0.13, k2 -0.31), taken smaller: at most ~3 px at the
  -- image's edges, the C920 being a low-distortion lens. Zero keeps the plain pinhole.
  distortion = { k1 = 0.10, k2 = -0.25 },
}
