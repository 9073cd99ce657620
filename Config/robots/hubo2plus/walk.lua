-- The Hubo2+'s walk: what differs from Config/common/walk.lua (every key is documented there).
-- The same ZMP walk as the small bodies, scaled by the body: the torso origin (between the hip yaw
-- joints) 0.757 m above the soles at the zero pose (OP3 0.28), the whole-body COM about 0.65 m up
-- with the knees bent, so the pendulum's time constant sqrt(z / g) is 0.26 s and the step time
-- grows with it; the hips 0.177 m apart, the soles 0.222 x 0.152 m. The drives' speeds (2.5-3.9
-- rad/s at the leg joints, Config/common/actuators.lua) bound how fast a foot can swing. The
-- measurements: docs/results/tuning.md, section "Hubo2+: walk".
return {
  -- timing and posture: the OP3's scaled by the body (above)
  tStep = 0.5,               -- s
  tZmp = 0.26,               -- s
  phSingle = { 0.15, 0.85 },
  bodyHeight = 0.69,         -- m (0.757 with straight legs)
  bodyTilt = 0.0,            -- rad: upright
  footY = 0.095,             -- m (the hips at 0.0885)
  stepHeight = 0.05,         -- m
  swingLead = 0.8,
  -- velocity and step limits, scaled to the body and the drives
  velLimitX = { -0.15, 0.35 },
  velLimitY = { -0.12, 0.12 },
  velLimitA = { -0.6, 0.6 },
  accLimit = { 0.2, 0.2, 0.6 },
  stepLimitX = { -0.08, 0.18 },
  stepLimitY = { 0.19, 0.31 },
  stepLimitA = { -0.05, 0.6 },
  -- arms hanging (the shoulders' zero has them 15 deg out; 0.1 rad in from there), elbows a little
  -- bent; LSP/RSP turn the arm about the torso's y axis, LSR/RSR about x
  arms = {
    l = { posture = { LSP = 0.0, LSR = -0.1, LSY = 0.0, LEB = -0.3, LWY = 0.0, LWP = 0.0 },
          pitch = 'LSP', roll = 'LSR' },
    r = { posture = { RSP = 0.0, RSR = 0.1, RSY = 0.0, REB = -0.3, RWY = 0.0, RWP = 0.0 },
          pitch = 'RSP', roll = 'RSR' },
  },
  headingMaxCorrection = 0.2,-- rad/s
  feedback = { maxCorrection = 0.2 }, -- rad
  -- balance on the ankle F/T sensors (the FFT boards of can.lua): the measured ZMP of both feet
  -- against the walk's, fed back into a shift of the COM
  balance = {
    zmpGain = { 2.0, 2.0 },  -- 1/s, standing (integral)
    walkGain = { 1.0, 0.0 }, -- 1/s, walking; not sideways: no measured gain there
    maxShift = 0.03,         -- m
    maxRate = 0.004,         -- m/s: a walk stopping into stance keeps the torso still
    minForce = 40.0,         -- N: 10% of the body's weight
    sensorHeight = 0.106,    -- m
  },
  -- kick: the OP3's structure with its distances scaled to the longer legs and its phases slowed
  -- to the drives' speeds. Not tuned and not a target (a 45 kg robot does not play KidSize
  -- football): it gives the kick states their data.
  kick = {
    supportY = 0.02,
    body = {
      { duration = 1.0, shift = 1, height = -0.002, lean = -0.01 },
      { duration = 0.8, shift = 1, height = -0.002 },
      { duration = 0.4, shift = 1, lean = -0.02, tilt = -0.1, arms = 0.2 },
      { duration = 0.6, shift = 1 },
      { duration = 0.6, shift = 1 },
      { duration = 1.0, shift = 0 },
    },
    leg = {
      { duration = 1.0 },
      { duration = 0.3, z = 0.06 },
      { duration = 0.5, x = -0.03, z = 0.08, hip = 0.3, knee = 0.6, ankle = 0.2, arm = 0.2 },
      { duration = 0.3, x = 0.15, z = 0.05, hip = -0.6, knee = 0.0, ankle = 0.1, arm = 0.1 },
      { duration = 0.3, x = 0.15, z = 0.05, hip = -0.6, knee = 0.0, ankle = 0.1, arm = 0.1 },
      { duration = 0.6, x = -0.03, z = 0.06 },
      { duration = 0.6 },
      { duration = 1.0 },
    },
  },
  -- stance and transitions: twice the OP3's time into the stance (the slower drives), arms and
  -- head at full hardness
  tStance = 2.0,             -- s
  hardnessArms = 1.0,
  hardnessHead = 1.0,
  -- fall detection
  fallAngle = 0.5,           -- rad
  fallRate = 1.5,            -- rad/s
  fallAngleRate = 0.3,       -- rad
  -- a 45 kg robot cannot get up by itself and must not go limp (a limp fall folds the legs under
  -- 45 kg): it takes a protective pose held stiff enough to keep its shape: knees bent (the torso
  -- comes down lower, slower), elbows bent (the forearms take the ground before the head), the arms
  -- thrown towards the fall (fallArms); lying still it holds the pose until someone puts it back
  -- on its feet
  fallPolicy = {
    standup = false,
    pose = {
      LHY = 0, LHR = 0, LHP = -0.6, LKN = 1.2, LAP = -0.6, LAR = 0,
      RHY = 0, RHR = 0, RHP = -0.6, RKN = 1.2, RAP = -0.6, RAR = 0,
      LSR = 0.2, LSY = 0, LEB = -1.2, LWY = 0, LWP = 0,
      RSR = -0.2, RSY = 0, REB = -1.2, RWY = 0, RWP = 0,
      WST = 0, NK1 = 0.3, NK2 = 0.3,   -- chin down
    },
    hardness = 0.7,          -- while falling and lying (held, not limp)
    rest = 'hold',           -- lying still: 'hold' the pose, or 'release' (torque off)
  },
}
