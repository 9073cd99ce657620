-- Joints of the DARwIn-OP / OP3 family, shared by Config/Sim and Config/OP: the order of every
-- joint array in shm (dcm.sensor, dcm.actuator), the groups, and the joint limits.
-- Angles: right-hand rule about the joint axes of shared/robots/op3_reference.txt, zero = the
-- reference zero pose (straight legs, arms down).
return {
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
  -- joint limits, rad { min, max }: kept inside the mechanical ranges
  limits = {
    head_pan = { -1.57, 1.57 }, head_tilt = { -1.2, 0.6 },
    l_sho_pitch = { -3.14, 3.14 }, l_sho_roll = { -1.6, 1.6 }, l_el = { -2.6, 2.6 },
    r_sho_pitch = { -3.14, 3.14 }, r_sho_roll = { -1.6, 1.6 }, r_el = { -2.6, 2.6 },
    l_hip_yaw = { -1.2, 1.2 }, l_hip_roll = { -0.8, 0.8 }, l_hip_pitch = { -2.0, 2.0 },
    l_knee = { -2.6, 2.6 }, l_ank_pitch = { -1.4, 1.4 }, l_ank_roll = { -0.8, 0.8 },
    r_hip_yaw = { -1.2, 1.2 }, r_hip_roll = { -0.8, 0.8 }, r_hip_pitch = { -2.0, 2.0 },
    r_knee = { -2.6, 2.6 }, r_ank_pitch = { -1.4, 1.4 }, r_ank_roll = { -0.8, 0.8 },
  },
}
