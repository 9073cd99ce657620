-- The DARwIn-OP's head camera (Logitech C905): vertical field of view 46 deg (ROBOTIS framework
-- Camera.h VIEW_V_ANGLE; shared/robots/darwin_reference.txt CAMERA).
return {
  fovy = math.rad(46),          -- rad
}
