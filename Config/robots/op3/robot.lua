-- The simulated robot: an OP3-class 20-joint humanoid (numbers from shared/robots/op3_reference.txt).
-- Joint angles follow the right-hand rule about each joint's axis in the robot description
-- (op3.urdf, beside this file); at zero every joint is in the reference zero pose (straight legs,
-- arms down). The servos turn the same way as these axes (direction +1 on the bus).
local joints = {
  'head_pan', 'head_tilt',
  'l_sho_pitch', 'l_sho_roll', 'l_el',
  'l_hip_yaw', 'l_hip_roll', 'l_hip_pitch', 'l_knee', 'l_ank_pitch', 'l_ank_roll',
  'r_hip_yaw', 'r_hip_roll', 'r_hip_pitch', 'r_knee', 'r_ank_pitch', 'r_ank_roll',
  'r_sho_pitch', 'r_sho_roll', 'r_el',
}

-- { joint = model } for every joint
local function every_joint(model)
  local t = {}
  for _, j in ipairs(joints) do t[j] = model end
  return t
end

return {
  name = 'op3',
  -- the robot description the sim and the kinematics read (relative to this folder)
  description = 'op3.urdf',
  -- joint order of every joint array in shm (dcm.sensor, dcm.actuator): the bus order
  joints = joints,
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
  -- each joint's actuator model (Config/common/actuators.lua): the sim drives every joint with its
  -- numbers, and Run/gen_urdf.py writes its torque, speed, damping and friction into op3.urdf
  actuator = every_joint('XM430-W350'),
  -- the kinematics' named chains (Lib/kinematics.lua): joints from the base to the tip (default:
  -- the group of the same name) and the tip, a frame of op3.urdf
  chains = {
    lleg = { tip = 'l_sole' }, rleg = { tip = 'r_sole' },
    larm = { tip = 'l_hand' }, rarm = { tip = 'r_hand' },
    head = { tip = 'camera_link' },
  },
  -- massless frames Run/gen_urdf.py adds to op3.urdf (the URDF carries them; nothing else reads
  -- this table): link = the link it is fixed to; xyz = its origin and rpy its orientation (URDF
  -- roll, pitch, yaw), both in the reference frame at the zero pose (soles on z = 0, x forward,
  -- y left, z up)
  frames = {
    -- optical centre = the reference's CAMERA point; x along the optical axis, z image-up: level
    camera_link = { link = 'head_tilt_link' },
    -- foot frames: on the sole below each ankle centre (ankle pitch axis x, ankle roll axis y)
    l_sole = { link = 'l_ank_roll_link', xyz = { 0.0001, 0.035, 0 } },
    r_sole = { link = 'r_ank_roll_link', xyz = { 0.0001, -0.035, 0 } },
    -- hand points: the far end of the elbow link's collision box
    l_hand = { link = 'l_el_link', xyz = { -0.001, 0.3254, 0.3802 } },
    r_hand = { link = 'r_el_link', xyz = { -0.001, -0.3255, 0.3802 } },
  },
}
