-- The simulated robot: an OP3-class 20-joint humanoid (numbers from shared/robots/op3_reference.txt).
-- Joint angles follow the right-hand rule about each joint's axis in the robot description
-- (Config/Sim/op3.urdf); at zero every joint is in the reference zero pose (straight legs, arms down).
return {
  name = 'op3',
  -- joint order of every joint array in shm (dcm.sensor, dcm.actuator)
  joints = {
    'head_pan', 'head_tilt',
    'l_sho_pitch', 'l_sho_roll', 'l_el',
    'l_hip_yaw', 'l_hip_roll', 'l_hip_pitch', 'l_knee', 'l_ank_pitch', 'l_ank_roll',
    'r_hip_yaw', 'r_hip_roll', 'r_hip_pitch', 'r_knee', 'r_ank_pitch', 'r_ank_roll',
    'r_sho_pitch', 'r_sho_roll', 'r_el',
  },
  groups = {
    head = { 'head_pan', 'head_tilt' },
    larm = { 'l_sho_pitch', 'l_sho_roll', 'l_el' },
    lleg = { 'l_hip_yaw', 'l_hip_roll', 'l_hip_pitch', 'l_knee', 'l_ank_pitch', 'l_ank_roll' },
    rleg = { 'r_hip_yaw', 'r_hip_roll', 'r_hip_pitch', 'r_knee', 'r_ank_pitch', 'r_ank_roll' },
    rarm = { 'r_sho_pitch', 'r_sho_roll', 'r_el' },
  },
  -- joint limits, rad: { min, max } per joint (from the OP3's mechanical ranges, kept inside them)
  limits = {
    head_pan = { -1.57, 1.57 }, head_tilt = { -1.2, 0.6 },
    l_sho_pitch = { -3.14, 3.14 }, l_sho_roll = { -1.6, 1.6 }, l_el = { -2.6, 2.6 },
    r_sho_pitch = { -3.14, 3.14 }, r_sho_roll = { -1.6, 1.6 }, r_el = { -2.6, 2.6 },
    l_hip_yaw = { -1.2, 1.2 }, l_hip_roll = { -0.8, 0.8 }, l_hip_pitch = { -2.0, 2.0 },
    l_knee = { -2.6, 2.6 }, l_ank_pitch = { -1.4, 1.4 }, l_ank_roll = { -0.8, 0.8 },
    r_hip_yaw = { -1.2, 1.2 }, r_hip_roll = { -0.8, 0.8 }, r_hip_pitch = { -2.0, 2.0 },
    r_knee = { -2.6, 2.6 }, r_ank_pitch = { -1.4, 1.4 }, r_ank_roll = { -0.8, 0.8 },
  },
  -- the robot description the sim and the kinematics read
  urdf = 'Config/Sim/op3.urdf',
  -- the DCM's control period, s
  period = 0.008,
}
