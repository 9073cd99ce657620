-- The HOAP-3's camera for the vision: one of its two eyes (the right, REYE: hoap3_reference.txt
-- CAMERA). The ref gives only the capture size (320 x 240, S9); the lens is unknown: the OP3's
-- webcam's vertical field of view (43.3 deg, chosen) as a plain pinhole. The image size and rate
-- stay the platform's (Config/common/camera.lua): the sim renders what the vision expects.
local fovy = math.rad(43.3)
local f = 240 / math.tan(fovy / 2)   -- px: the pinhole of fovy over 480 rows
return {
  fovy = fovy,                  -- rad
  intrinsics = { fx = f, fy = f, cx = 319.5, cy = 239.5 },   -- OpenCV's convention
  distortion = { k1 = 0, k2 = 0 },
  head_joint = { 21, 22 },      -- 0-based indices of head_pan, head_tilt in the joint order (robot.lua)
}
