-- The HOAP-3's walk: what differs from Config/common/walk.lua (every key is documented there).
-- The body: the torso origin (between the hip yaw joints) 0.25 m above the soles with straight legs
-- (the OP3's height), thigh and shank 0.105 m, the hips 0.078 m apart, the soles 0.108 x 0.073 m;
-- but 8.8 kg on drives of 3 and 4.5 N*m (the OP3: 3.15 kg on 5 N*m): the knees carry the body in
-- single support only while they are nearly straight, so it stands tall and takes short, slow
-- steps. The whole-body COM sits about 0.30 m above the soles standing (S0's z_c = 0.32 m).
return {
  -- timing
  tStep = 0.4,               -- s
  tZmp = 0.175,              -- s: sqrt(0.30 / 9.81)
  phSingle = { 0.15, 0.85 },
  -- posture: the knees bent 35 deg at 0.24 m, where a knee in single support carries the 7.9 kg
  -- above it at 3.2 cm, 2.5 of its 4.5 N*m (at 0.23 m: 50 deg, 3.4 N*m)
  bodyHeight = 0.24,         -- m
  -- the torso leans forward: the upper body's COM (trunk, head and hanging arms, 5.9 kg) is 2.7 cm
  -- behind the hip axes upright, 1.5 N*m on 3 N*m hip pitch drives (upright, random commands tip
  -- it backwards: a fall on 1 of 3 seeds at 0.05 rad, on none of 5 at 0.1 or 0.15); 0.15 rad over
  -- the COM's 0.17 m height above the hips puts it over them
  bodyTilt = 0.15,           -- rad
  footY = 0.044,             -- m: the hips at 0.039, the soles' centres at 0.044 (S1 foot frames)
  stepHeight = 0.025,        -- m
  -- the soles about the ankle point: toe 0.068, heel 0.040, inner edge 0.0315 (hoap3_reference.txt)
  sole = { toe = 0.068, heel = 0.040, inner = 0.0315 },
  -- velocity and step limits: short steps
  velLimitX = { -0.06, 0.15 },
  velLimitY = { -0.05, 0.05 },
  velLimitA = { -0.5, 0.5 },
  accLimit = { 0.15, 0.15, 0.5 },
  stepLimitX = { -0.03, 0.06 },
  stepLimitY = { 0.078, 0.13 },
  stepLimitA = { -0.05, 0.45 },
  -- arms hanging at the sides (shoulder pitch +pi/2 from the zero pose's arms forward), a little out
  -- and the elbows a little bent; the shoulder pitch swings them about the torso's y axis. No roll
  -- joint for feedback: the walk takes each joint's axis at the zero pose, where the shoulder roll
  -- turns the forward-pointing arm about z, not about x.
  arms = {
    l = { posture = { l_sho_pitch = 1.5708, l_sho_roll = 0.1, l_arm_yaw = 0, l_el = -0.3, l_wrist_yaw = 0 },
          pitch = 'l_sho_pitch' },
    r = { posture = { r_sho_pitch = 1.5708, r_sho_roll = -0.1, r_arm_yaw = 0, r_el = -0.3, r_wrist_yaw = 0 },
          pitch = 'r_sho_pitch' },
  },
  -- the measured ZMP: the four pressure sensors under each foot (robot.lua foot_pressure), as on the
  -- real HOAP-3, not the sim's ankle F/T (so no sensorHeight here); balance feedback stays off, the
  -- default
  tStance = 2.0,             -- s
  -- falling: the OP3's arm poses (1.2 rad forward of hanging, 0.8 behind) in this body's zero (arms
  -- forward): about the torso's y axis, both arms, falling forwards, backwards
  fallArms = { 0.37, 2.37 },
  -- no stand-up motions are written for this body yet: it falls into a protective pose (knees bent,
  -- arms towards the fall: fallArms), held while it falls, and lies still with the torque released
  -- until someone puts it back on its feet
  fallPolicy = {
    standup = false,
    pose = {
      l_hip_yaw = 0, l_hip_roll = 0, l_hip_pitch = -0.5, l_knee = 1.0, l_ank_pitch = -0.5, l_ank_roll = 0,
      r_hip_yaw = 0, r_hip_roll = 0, r_hip_pitch = -0.5, r_knee = 1.0, r_ank_pitch = -0.5, r_ank_roll = 0,
      l_sho_roll = 0.1, l_arm_yaw = 0, l_el = -0.5, l_wrist_yaw = 0,
      r_sho_roll = -0.1, r_arm_yaw = 0, r_el = -0.5, r_wrist_yaw = 0,
      waist_pitch = 0, head_pan = 0, head_tilt = 0, head_roll = 0,
    },
    hardness = 0.5,
    rest = 'release',
  },
  hardnessArms = 1.0,
  hardnessHead = 1.0,
}
