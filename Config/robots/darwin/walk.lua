-- The DARwIn-OP's walk: what differs from Config/common/walk.lua (every key is documented there).
-- The OP3's walk with the posture and step limits scaled to the DARwIn-OP's shorter legs (hip
-- 0.2195 m above the soles against 0.25) and narrower hips (0.037 m); the measurements:
-- docs/results/tuning.md, section "DARwIn-OP: walk".
return {
  tZmp = 0.155,              -- s: the lower COM
  -- posture
  bodyHeight = 0.225,        -- m, torso origin (the hip yaw anchors) above the ground
  footY = 0.037,             -- m: the hips' half spacing
  stepHeight = 0.03,         -- m
  -- velocity and step limits: the OP3's scaled to the shorter legs; turning opens the feet (toed
  -- out) only, no turnToeIn on this body
  velLimitX = { -0.12, 0.30 },
  velLimitY = { -0.12, 0.12 },
  velLimitA = { -1.8, 1.8 },
  stepLimitX = { -0.05, 0.09 },
  stepLimitY = { 0.074, 0.14 },
  stepLimitA = { -0.05, 0.95 },
  arms = {
    l = { posture = { l_sho_pitch = 0.0, l_sho_roll = -0.25, l_el = 0.0 }, pitch = 'l_sho_pitch', roll = 'l_sho_roll' },
    r = { posture = { r_sho_pitch = 0.0, r_sho_roll = 0.25, r_el = 0.0 }, pitch = 'r_sho_pitch', roll = 'r_sho_roll' },
  },
  -- the ankle roll axis above the sole (the real DARwIn-OP has no F/T sensors: balance stays off)
  balance = { sensorHeight = 0.0335 },
  -- kick: the OP3's structure (Config/common/walk.lua) retuned for this body in the sim
  -- (Tools/tune/kick_tune.sh with ROBOT=darwin); the MX-28's 5.24 rad/s limits the toe to
  -- ~1.7 m/s at the ball
  kick = {
    body = {
      -- weight over the support foot
      { duration = 0.6, shift = 1, height = -0.001, lean = -0.008 },
      { duration = 0.511, shift = 1, height = -0.001, lean = 0.0 },
      -- torso back, arms back, through the swing
      { duration = 0.248, shift = 1, height = 0.008, lean = -0.01, tilt = -0.174, arms = 0.326 },
      -- upright again, then the weight back to the middle
      { duration = 0.35, shift = 1, lean = 0.01 },
      { duration = 0.35, shift = 1 },
      { duration = 0.5, shift = 0 },
    },
    leg = {
      { duration = 0.6 },
      -- lift, then wind up: foot back and up, knee bent, toe down
      { duration = 0.115, z = 0.036 },
      { duration = 0.401, x = 0.003, z = 0.044, hip = 0.506, knee = 1.034, ankle = 0.395, arm = 0.275 },
      -- swing: a short phase, so the servos run at their speed limit; follow through
      { duration = 0.048, x = 0.077, z = 0.011, hip = -1.174, knee = -0.202, ankle = 0.104, arm = 0.206 },
      { duration = 0.101, x = 0.077, z = 0.011, hip = -1.174, knee = -0.202, ankle = 0.104, arm = 0.206 },
      -- back, down
      { duration = 0.384, x = -0.05, z = 0.048, hip = 0.259, knee = -0.045, ankle = -0.175 },
      { duration = 0.35 },
      { duration = 0.5 },
    },
  },
}
