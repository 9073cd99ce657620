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
  -- the DCM's safe state when motion dies or stops answering (Modules/dcm/guard.c): from the pose of
  -- the trip into this crouch within `ramp` s, held at the platform's safe_hardness; joints not named
  -- stay where they were. Both feet flat under the hips, the torso 0.22 m above the soles (the walk
  -- stands at 0.25), tilted 0.08 rad forward: the legs' IK of that stance (Lib/kinematics.lua).
  safe_pose = {
    ramp = 0.3,
    q = {
      l_hip_yaw = -0.005, l_hip_roll = -0.062, l_hip_pitch = -0.732, l_knee = 1.495, l_ank_pitch = 0.844,
      l_ank_roll = -0.062,
      r_hip_yaw = 0.005, r_hip_roll = 0.062, r_hip_pitch = 0.732, r_knee = -1.495, r_ank_pitch = -0.844,
      r_ank_roll = 0.062,
    },
  },
  -- 6-axis force/torque at the ankles (dcm.sensor.ft), the sim's instruments: the real OP3 has none,
  -- so on PLATFORM=OP these slots read 0
  ft = { lfoot = 'l_ank_roll', rfoot = 'r_ank_roll' },
  -- joint limits, rad { min, max }: kept inside the mechanical ranges; `knee` is l_knee's and r_knee's
  -- (a joint of both sides named once: Lib/Config.lua)
  limits = {
    head_pan = { -1.57, 1.57 }, head_tilt = { -1.2, 0.6 },
    sho_pitch = { -3.14, 3.14 }, sho_roll = { -1.6, 1.6 }, el = { -2.6, 2.6 },
    hip_yaw = { -1.2, 1.2 }, hip_roll = { -0.8, 0.8 }, hip_pitch = { -2.0, 2.0 },
    knee = { -2.6, 2.6 }, ank_pitch = { -1.4, 1.4 }, ank_roll = { -0.8, 0.8 },
  },
  -- the Dynamixel bus on the OP platform (Platforms/OP), in the form of ROBOTIS' .robot files
  -- (op3_manager/config/OP3.robot): the buses (port, baud rate; `--port` overrides bus 1's), then one
  -- row per servo (the joint it drives) or board (IMU, buttons), in any order. ROBOTIS numbering:
  -- odd = right side, even = left side, 19/20 = head. direction +1 and zero 2048 everywhere: the
  -- URDF's axes are the servos' own:  angle (rad) = direction * (count - zero) * 2*pi / 4096.
  -- The OpenCR's IMU axes are taken as the torso's (no reference data on its mounting yet).
  buses = {
    { port = '/dev/ttyUSB0', baud = 1000000 },   -- the OpenCR (USB CDC)
  },
  devices = {
    { joint = 'head_pan',    bus = 1, id = 19, model = 'XM430-W350', protocol = 2, direction = 1, zero = 2048 },
    { joint = 'head_tilt',   bus = 1, id = 20, model = 'XM430-W350', protocol = 2, direction = 1, zero = 2048 },
    { joint = 'l_sho_pitch', bus = 1, id =  2, model = 'XM430-W350', protocol = 2, direction = 1, zero = 2048 },
    { joint = 'l_sho_roll',  bus = 1, id =  4, model = 'XM430-W350', protocol = 2, direction = 1, zero = 2048 },
    { joint = 'l_el',        bus = 1, id =  6, model = 'XM430-W350', protocol = 2, direction = 1, zero = 2048 },
    { joint = 'l_hip_yaw',   bus = 1, id =  8, model = 'XM430-W350', protocol = 2, direction = 1, zero = 2048 },
    { joint = 'l_hip_roll',  bus = 1, id = 10, model = 'XM430-W350', protocol = 2, direction = 1, zero = 2048 },
    { joint = 'l_hip_pitch', bus = 1, id = 12, model = 'XM430-W350', protocol = 2, direction = 1, zero = 2048 },
    { joint = 'l_knee',      bus = 1, id = 14, model = 'XM430-W350', protocol = 2, direction = 1, zero = 2048 },
    { joint = 'l_ank_pitch', bus = 1, id = 16, model = 'XM430-W350', protocol = 2, direction = 1, zero = 2048 },
    { joint = 'l_ank_roll',  bus = 1, id = 18, model = 'XM430-W350', protocol = 2, direction = 1, zero = 2048 },
    { joint = 'r_hip_yaw',   bus = 1, id =  7, model = 'XM430-W350', protocol = 2, direction = 1, zero = 2048 },
    { joint = 'r_hip_roll',  bus = 1, id =  9, model = 'XM430-W350', protocol = 2, direction = 1, zero = 2048 },
    { joint = 'r_hip_pitch', bus = 1, id = 11, model = 'XM430-W350', protocol = 2, direction = 1, zero = 2048 },
    { joint = 'r_knee',      bus = 1, id = 13, model = 'XM430-W350', protocol = 2, direction = 1, zero = 2048 },
    { joint = 'r_ank_pitch', bus = 1, id = 15, model = 'XM430-W350', protocol = 2, direction = 1, zero = 2048 },
    { joint = 'r_ank_roll',  bus = 1, id = 17, model = 'XM430-W350', protocol = 2, direction = 1, zero = 2048 },
    { joint = 'r_sho_pitch', bus = 1, id =  1, model = 'XM430-W350', protocol = 2, direction = 1, zero = 2048 },
    { joint = 'r_sho_roll',  bus = 1, id =  3, model = 'XM430-W350', protocol = 2, direction = 1, zero = 2048 },
    { joint = 'r_el',        bus = 1, id =  5, model = 'XM430-W350', protocol = 2, direction = 1, zero = 2048 },
    { board = 'OpenCR', bus = 1, id = 200, protocol = 2,
      gyro_axes = { 'x', 'y', 'z' }, accel_axes = { 'x', 'y', 'z' } },
  },
  -- each joint's actuator model (Config/common/actuators.lua): the sim drives every joint with its
  -- numbers, and Tools/urdf/gen_urdf.py writes its torque, speed, damping and friction into op3.urdf
  actuator = every_joint('XM430-W350'),
  -- massless frames Tools/urdf/gen_urdf.py adds to op3.urdf (the URDF carries them; nothing else reads
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
