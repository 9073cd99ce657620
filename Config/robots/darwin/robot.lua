-- The ROBOTIS DARwIn-OP: 20 joints, MX-28 servos on protocol 1.0, CM-730 sub-controller.
-- Interim: the joint convention is still the OP3's (same names, axes and zero pose as
-- Config/robots/op3); the kinematic and mass model below is hand-made (see its notes).
-- Kinematic and mass model (Lib/kinematics.lua). Same conventions as the OP3
-- model in Config/robots/op3/robot.lua: reference frame = the robot at its zero pose, soles on z = 0,
-- x forward, y left, z up, metres; per joint: parent (nil = torso), axis, anchor (a point on the
-- axis), mass and centre of mass of the link it moves. The axes and the zero pose (straight legs,
-- arms out sideways) follow the OP3 reference, so Lua code is the same on both robots; the OP DCM
-- maps servo directions and zero offsets onto them.
--
-- Geometry: thigh 0.093, tibia 0.093, ankle to sole 0.0335, hip offset y 0.037 (DARwIn-OP spec);
-- hip yaw axis 0.028652 above the hip roll/pitch centre; shoulders 0.082 out and 0.122 above
-- the hips, upper arm 0.060, lower arm 0.129; neck 0.1725 above the hips and 0.013 forward
-- (UPenn's DARwIn-OP kinematics constants). The camera offset from the neck (0.0332 forward,
-- 0.0344 up) is approximate.
-- Masses: ROBOTIS' DARwIn-OP URDF (darwin.urdf: MP_BODY 0.9756, MP_PELVIS 0.167, MP_THIGH1/2
-- 0.1190, MP_TIBIA 0.0703, MP_ANKLE1 0.1671, MP_ANKLE2 0.0794, MP_SHOULDER 0.0259, MP_ARM_HIGH
-- 0.1684, MP_ARM_LOW 0.0593, MP_NECK 0.0244, MP_HEAD 0.1580 kg; that file gives the right pelvis
-- 0.197, taken here as 0.167 like the left). Total 3.11 kg (published robot: about 2.9 kg).
-- The centres of mass are placed by hand at each link's geometric centre (approximate: the URDF
-- gives them in rotated link frames that were not transcribed).
local H = 0.2195 -- hip roll/pitch centre height
local A = 0.0335 -- ankle height
local K = A + 0.093 -- knee height
local S = H + 0.122 -- shoulder height
local N = H + 0.1725 -- neck (pan/tilt) height

return {
  name = 'darwin',
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
  -- the Dynamixel bus on the OP platform (Platforms/OP): ROBOTIS numbering; ids in joint order
  devices = {
    protocol = 1,             -- Dynamixel protocol 1.0
    servo = 'MX-28',
    board = 'CM-730',
    board_id = 200,
    ids = { 19, 20, 2, 4, 6, 8, 10, 12, 14, 16, 18, 7, 9, 11, 13, 15, 17, 1, 3, 5 },
    direction = { 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1 },
    zero = { 2048, 2048, 2048, 2048, 2048, 2048, 2048, 2048, 2048, 2048, 2048, 2048, 2048, 2048, 2048, 2048,
      2048, 2048, 2048, 2048 },
  },
  -- the DCM's control period, s (125 Hz)
  period = 0.008,
  kinematics = {
    -- torso-frame origin: between the hip yaw axes at the hip yaw joint's height
    origin = { 0, 0, H + 0.028652 },
    torso = { mass = 0.97559947, com = { -0.003, 0, H + 0.08 } },
    joints = {
      head_pan = { axis = { 0, 0, 1 }, anchor = { 0.013, 0, N },
        mass = 0.024357719, com = { 0.013, 0, N - 0.007 } },
      head_tilt = { parent = 'head_pan', axis = { 0, -1, 0 }, anchor = { 0.013, 0, N },
        mass = 0.15804192, com = { 0.013, 0, N + 0.0186 } },
      l_sho_pitch = { axis = { 0, 1, 0 }, anchor = { 0, 0.082, S }, mass = 0.025913024, com = { 0, 0.092, S } },
      l_sho_roll = { parent = 'l_sho_pitch', axis = { -1, 0, 0 }, anchor = { 0, 0.082, S },
        mass = 0.16837715, com = { 0, 0.118, S } },
      l_el = { parent = 'l_sho_roll', axis = { 1, 0, 0 }, anchor = { 0, 0.142, S },
        mass = 0.059288504, com = { 0, 0.2, S } },
      r_sho_pitch = { axis = { 0, -1, 0 }, anchor = { 0, -0.082, S },
        mass = 0.025913024, com = { 0, -0.092, S } },
      r_sho_roll = { parent = 'r_sho_pitch', axis = { -1, 0, 0 }, anchor = { 0, -0.082, S },
        mass = 0.16837715, com = { 0, -0.118, S } },
      r_el = { parent = 'r_sho_roll', axis = { 1, 0, 0 }, anchor = { 0, -0.142, S },
        mass = 0.059288504, com = { 0, -0.2, S } },
      l_hip_yaw = { axis = { 0, 0, -1 }, anchor = { 0, 0.037, H + 0.028652 },
        mass = 0.167, com = { 0, 0.037, H + 0.0185 } },
      l_hip_roll = { parent = 'l_hip_yaw', axis = { -1, 0, 0 }, anchor = { 0, 0.037, H },
        mass = 0.11904336, com = { 0, 0.037, H } },
      l_hip_pitch = { parent = 'l_hip_roll', axis = { 0, 1, 0 }, anchor = { 0, 0.037, H },
        mass = 0.11904336, com = { 0, 0.037, H - 0.063 } },
      l_knee = { parent = 'l_hip_pitch', axis = { 0, 1, 0 }, anchor = { 0, 0.037, K },
        mass = 0.070309794, com = { 0, 0.037, K - 0.054 } },
      l_ank_pitch = { parent = 'l_knee', axis = { 0, -1, 0 }, anchor = { 0, 0.037, A },
        mass = 0.16710792, com = { 0, 0.037, A } },
      l_ank_roll = { parent = 'l_ank_pitch', axis = { 1, 0, 0 }, anchor = { 0, 0.037, A },
        mass = 0.0794462, com = { 0, 0.037, A - 0.026 } },
      r_hip_yaw = { axis = { 0, 0, -1 }, anchor = { 0, -0.037, H + 0.028652 },
        mass = 0.167, com = { 0, -0.037, H + 0.0185 } },
      r_hip_roll = { parent = 'r_hip_yaw', axis = { -1, 0, 0 }, anchor = { 0, -0.037, H },
        mass = 0.11904336, com = { 0, -0.037, H } },
      r_hip_pitch = { parent = 'r_hip_roll', axis = { 0, -1, 0 }, anchor = { 0, -0.037, H },
        mass = 0.11904336, com = { 0, -0.037, H - 0.063 } },
      r_knee = { parent = 'r_hip_pitch', axis = { 0, -1, 0 }, anchor = { 0, -0.037, K },
        mass = 0.070309794, com = { 0, -0.037, K - 0.054 } },
      r_ank_pitch = { parent = 'r_knee', axis = { 0, 1, 0 }, anchor = { 0, -0.037, A },
        mass = 0.16710792, com = { 0, -0.037, A } },
      r_ank_roll = { parent = 'r_ank_pitch', axis = { 1, 0, 0 }, anchor = { 0, -0.037, A },
        mass = 0.0794462, com = { 0, -0.037, A - 0.026 } },
    },
    sole = { l = { 0, 0.037, 0 }, r = { 0, -0.037, 0 } },
    hand = { l = { 0, 0.271, S }, r = { 0, -0.271, S } },
    camera = { 0.013 + 0.0332, 0, N + 0.0344 },
  },
}
