-- The DARwIn-OP's head camera (Logitech C905): vertical field of view 46 deg (ROBOTIS framework
-- Camera.h VIEW_V_ANGLE; shared/robots/darwin_reference.txt CAMERA). The calibration is robot data
-- shared by the sim's renderer and the vision's projection (as Config/robots/op3/camera.lua).
local fovy = math.rad(46)
local f = 240 / math.tan(fovy / 2)   -- px: the pinhole of fovy over 480 rows
return {
  fovy = fovy,                  -- rad
  intrinsics = { fx = f, fy = f, cx = 319.5, cy = 239.5 },   -- OpenCV's convention
  -- no calibration of the C905 in the robot data: the plain pinhole until a robot is calibrated
  distortion = { k1 = 0, k2 = 0 },
}
