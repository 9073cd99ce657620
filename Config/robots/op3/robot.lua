-- The simulated robot: an OP3-class 20-joint humanoid (numbers from shared/robots/op3_reference.txt).
-- Joint angles follow the right-hand rule about each joint's axis in the robot description
-- (op3.urdf, beside this file); at zero every joint is in the reference zero pose (straight legs,
-- arms down). The servos turn the same way as these axes (direction +1 on the bus).
return {
  name = 'op3',
  -- the robot description the sim and the kinematics read (relative to this folder)
  description = 'op3.urdf',
  -- joint order of every joint array in shm (dcm.sensor, dcm.actuator): the bus order
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
  -- the Dynamixel bus on the OP platform (Platforms/OP): ROBOTIS numbering, odd = right side,
  -- even = left side, 19/20 = head; ids in joint order
  devices = {
    protocol = 2,             -- Dynamixel protocol 2.0
    servo = 'XM430',
    board = 'OpenCR',
    board_id = 200,
    ids = { 19, 20, 2, 4, 6, 8, 10, 12, 14, 16, 18, 7, 9, 11, 13, 15, 17, 1, 3, 5 },
    direction = { 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1 },
    zero = { 2048, 2048, 2048, 2048, 2048, 2048, 2048, 2048, 2048, 2048, 2048, 2048, 2048, 2048, 2048, 2048,
      2048, 2048, 2048, 2048 },
  },
  -- the DCM's control period, s
  period = 0.008,
  -- kinematic and mass model (Lib/kinematics.lua), numbers from shared/robots/op3_reference.txt:
  -- per joint, in the reference frame at the zero pose (soles on z=0, x forward, y left, z up):
  -- parent joint (nil = torso), axis, anchor (a point on the axis), mass (kg) and centre of mass of
  -- the link the joint moves. Torso-frame origin (`origin`): between the hip yaw axes at their
  -- anchor height, the origin of body_link in op3.urdf.
  kinematics = {
    origin = { 0, 0, 0.27915 },
    torso = { mass = 1.34928, com = { -0.01501, 0.00013, 0.34497 } },
    joints = {
      head_pan = { axis = { 0, 0, 1 }, anchor = { -0.001, 0, 0.41565 },
        mass = 0.01176, com = { 0.00133, 0, 0.42388 } },
      head_tilt = { parent = 'head_pan', axis = { 0, -1, 0 }, anchor = { 0.009, 0.019, 0.44415 },
        mass = 0.13631, com = { 0.0113, 0.00037, 0.47185 } },
      l_sho_pitch = { axis = { 0, 1, 0 }, anchor = { -0.001, 0.06, 0.39015 },
        mass = 0.01176, com = { -0.001, 0.06823, 0.38782 } },
      l_sho_roll = { parent = 'l_sho_pitch', axis = { -1, 0, 0 }, anchor = { 0.018, 0.0885, 0.38015 },
        mass = 0.17758, com = { -0.00044, 0.13364, 0.38043 } },
      l_el = { parent = 'l_sho_roll', axis = { 1, 0, 0 }, anchor = { 0.018, 0.1789, 0.38005 },
        mass = 0.04127, com = { -0.001, 0.24923, 0.38385 } },
      r_sho_pitch = { axis = { 0, -1, 0 }, anchor = { -0.001, -0.06, 0.39015 },
        mass = 0.01176, com = { -0.001, -0.06823, 0.38782 } },
      r_sho_roll = { parent = 'r_sho_pitch', axis = { -1, 0, 0 }, anchor = { 0.018, -0.0885, 0.38015 },
        mass = 0.17758, com = { -0.00044, -0.13364, 0.38043 } },
      r_el = { parent = 'r_sho_roll', axis = { 1, 0, 0 }, anchor = { 0.018, -0.1789, 0.38005 },
        mass = 0.04127, com = { -0.001, -0.24923, 0.38385 } },
      l_hip_yaw = { axis = { 0, 0, -1 }, anchor = { 0, 0.035, 0.27915 },
        mass = 0.01181, com = { -0.00157, 0.035, 0.27141 } },
      l_hip_roll = { parent = 'l_hip_yaw', axis = { -1, 0, 0 }, anchor = { -0.024, 0.035, 0.25065 },
        mass = 0.17886, com = { -0.02012, 0.03528, 0.23851 } },
      l_hip_pitch = { parent = 'l_hip_roll', axis = { 0, 1, 0 }, anchor = { 0.0001, 0.054, 0.25065 },
        mass = 0.11543, com = { 0.00069, 0.03499, 0.16657 } },
      l_knee = { parent = 'l_hip_pitch', axis = { 0, 1, 0 }, anchor = { 0.0001, 0.054, 0.1405 },
        mass = 0.04015, com = { 0.0001, 0.03249, 0.0855 } },
      l_ank_pitch = { parent = 'l_knee', axis = { 0, -1, 0 }, anchor = { 0.0001, 0.054, 0.0305 },
        mass = 0.17886, com = { -0.02012, 0.03528, 0.04264 } },
      l_ank_roll = { parent = 'l_ank_pitch', axis = { 1, 0, 0 }, anchor = { -0.024, 0.035, 0.0305 },
        mass = 0.06934, com = { -0.00027, 0.04537, 0.0029 } },
      r_hip_yaw = { axis = { 0, 0, -1 }, anchor = { 0, -0.035, 0.27915 },
        mass = 0.01181, com = { -0.00157, -0.035, 0.27141 } },
      r_hip_roll = { parent = 'r_hip_yaw', axis = { -1, 0, 0 }, anchor = { -0.024, -0.035, 0.25065 },
        mass = 0.17886, com = { -0.02012, -0.03528, 0.23851 } },
      r_hip_pitch = { parent = 'r_hip_roll', axis = { 0, -1, 0 }, anchor = { 0.0001, -0.054, 0.25065 },
        mass = 0.11543, com = { 0.00069, -0.03499, 0.16657 } },
      r_knee = { parent = 'r_hip_pitch', axis = { 0, -1, 0 }, anchor = { 0.0001, -0.054, 0.1405 },
        mass = 0.04015, com = { 0.0001, -0.03249, 0.0855 } },
      r_ank_pitch = { parent = 'r_knee', axis = { 0, 1, 0 }, anchor = { 0.0001, -0.054, 0.0305 },
        mass = 0.17886, com = { -0.02012, -0.03528, 0.04264 } },
      r_ank_roll = { parent = 'r_ank_pitch', axis = { 1, 0, 0 }, anchor = { -0.024, -0.035, 0.0305 },
        mass = 0.06934, com = { -0.00027, -0.04537, 0.0029 } },
    },
    -- foot-frame origins: the sole point below each ankle centre
    sole = { l = { 0.0001, 0.035, 0 }, r = { 0.0001, -0.035, 0 } },
    -- hand points: the far end of the elbow link's collision box
    hand = { l = { -0.001, 0.3254, 0.3802 }, r = { -0.001, -0.3255, 0.3802 } },
    -- camera optical centre on the head_tilt link (looking along +x at the zero pose)
    camera = { 0.02325, 0, 0.4939 },
  },
}
