-- Walk parameters of the Hubo2+ (Player/Motion/walk.lua, the same ZMP walk as the small bodies).
-- Units: m, s, rad. Scaled from the OP3's by the body: the torso origin (between the hip yaw
-- joints) 0.757 m above the soles at the zero pose (OP3 0.28), the whole-body COM about 0.65 m up
-- with the knees bent, so the pendulum's time constant sqrt(z / g) is 0.26 s (OP3 0.165) and the
-- step time grows with it; the hips 0.177 m apart, the soles 0.222 x 0.152 m. The drives' speeds
-- (2.5-3.9 rad/s at the leg joints, Config/common/actuators.lua) bound how fast a foot can swing.
-- Measured in the sim (lockstep, seeds 1-3, Tests/motion/hubo_walk_test.sh): forward 0.302 m/s at
-- a 0.30 command for 30 s, sideways 0.120, backwards 0.117, turning 0.59 rad/s, 60 s of random
-- commands, no fall. With the velocity limits raised (sim_scenarios.lua 'speed', WALK_PARAMS) it
-- walks 0.46 m/s forward (falls at 0.5), 0.135 m/s sideways (falls at 0.2), turns 0.93 rad/s.
-- Changeable while the robot walks: Walk.set('name', value) from the REPL.
return {
  -- timing
  tStep = 0.5,               -- s, one step
  tZmp = 0.26,               -- s, sqrt(COM height / g) of the linear inverted pendulum
  phSingle = { 0.15, 0.85 }, -- phase of the step where single support begins and ends
  -- engine (read at the motion process's start): 'analytic', the COM solved step by step
  -- (Player/Motion/walk.lua), or 'preview', ZMP preview control over the planned steps
  -- (Player/Motion/walk_preview.lua: window in s, weights of the ZMP error and the COM jerk, lead-in s)
  engine = 'analytic',
  preview = { window = 1.6, Qe = 1.0, R = 1e-6, lead = 0.4 },
  -- step adjustment (capture point, Player/Motion/step_adjust.lua): the swing foot lands gain x the
  -- capture point's error beyond the dead band (m) further, at most max (m), within the step limits
  -- (moved while it travels); a sideways error beyond switchError (m) at a step's start swings the
  -- foot on the push's side; beyond touchdownError (m) a swing foot on the far side is put down
  -- within touchdownTime (s) and the step ends; the swing foot's ankle turns against the torso's
  -- tilt (IMU) by level (fraction: roll, pitch) so that it lands flat, faded over levelTime (s) once
  -- it carries. gain = 0: off
  stepAdjust = { gain = 0, deadband = { 0.01, 0.01 }, max = { 0.05, 0.08 }, switchError = 0.03,
    touchdownError = 0.04, touchdownTime = 0.05, level = { 1.0, 1.0 }, levelTime = 0.15 },
  -- posture
  bodyHeight = 0.69,         -- m, torso origin above the ground (0.757 with straight legs)
  bodyTilt = 0.0,            -- rad, torso pitch (forward positive)
  footX = 0.0,               -- m, trim of the torso origin behind the planned COM
  footY = 0.095,             -- m, half the lateral spacing of the feet (ankle points; hips at 0.0885)
  supportX = 0.0,            -- m, ZMP in single support, ahead of the ankle
  supportY = 0.0,            -- m, ZMP in single support, outward from the ankle
  stepHeight = 0.05,         -- m, swing foot lift
  swingLead = 0.8,           -- fraction of single support in which the swing foot reaches its place
  -- velocity: limits and acceleration (per second)
  velLimitX = { -0.15, 0.35 },
  velLimitY = { -0.12, 0.12 },
  velLimitA = { -0.6, 0.6 },
  accLimit = { 0.2, 0.2, 0.6 },
  -- steps: swing foot relative to the support foot (y, a measured outward)
  stepLimitX = { -0.08, 0.18 },
  stepLimitY = { 0.19, 0.31 },
  stepLimitA = { -0.05, 0.6 },
  -- arms, by joint name: hanging (the shoulders' zero has them 15 deg out; 0.1 rad in from there),
  -- elbows a little bent; LSP/RSP turn the arm about the torso's y axis, LSR/RSR about x
  arms = {
    l = { posture = { LSP = 0.0, LSR = -0.1, LSY = 0.0, LEB = -0.3, LWY = 0.0, LWP = 0.0 },
          pitch = 'LSP', roll = 'LSR' },
    r = { posture = { RSP = 0.0, RSR = 0.1, RSY = 0.0, REB = -0.3, RWY = 0.0, RWP = 0.0 },
          pitch = 'RSP', roll = 'RSR' },
  },
  armSwing = 0.0,            -- rad of arm pitch per m of foot lead
  hipRollCompensation = 0.0, -- rad, support hip roll added in single support
  -- heading: the IMU's yaw follows the integral of the commanded turning rate
  headingGain = 1.0,         -- rad/s of extra turning per rad of heading error
  headingMaxCorrection = 0.2,-- rad/s
  -- feedback: rotations about the torso's x (roll) and y (pitch) axes, restoring when positive
  feedback = {
    gyroTimeConstant = 0.02,    -- s, low-pass on the gyro
    gyroDeadband = { 0.0, 0.0 },-- rad/s
    ankle = { 0.2, 0.15 },      -- rad per rad/s: { roll, pitch }
    knee = 0.0,                 -- pitch
    hip = { 0.1, 0.0 },         -- { roll, pitch }
    arm = { 0.0, 0.0 },         -- { roll, pitch }
    torso = { 0.0, 0.0 },       -- rad per rad of torso angle error (proprioception): { roll, pitch }
    torsoTimeConstant = 0.05,   -- s
    tilt = { 0.0, 0.0 },        -- rad per rad of the IMU's tilt on the ankles (off: not tried on this body)
    tiltTimeConstant = 0.05,    -- s, low-pass on that tilt
    maxCorrection = 0.2,        -- rad, per joint
  },
  -- balance on the ankle F/T sensors (Player/Motion/balance.lua; the FFT boards of can.lua): the
  -- measured ZMP of both feet against the walk's, fed back into a shift of the COM
  balance = {
    zmpGain = { 2.0, 2.0 },  -- 1/s, standing, { x, y }: COM shift rate per m of ZMP error (integral)
    walkGain = { 1.0, 0.0 }, -- 1/s, walking (the step's ZMP swing filtered out: walkFilterTime); not
                             -- sideways: no measured gain there (hubo_balance_test walking 0.25 m/s:
                             -- y error RMS 67 mm off, 61 with { 1, 0 }, 62 with { 1, 1 })
    leakTime = 2.0,          -- s: the shift decays with this time constant
    maxShift = 0.03,         -- m, per axis
    maxRate = 0.004,         -- m/s: the shift moves no faster (a short push: balance.lua; a walk
                             -- stopping into stance: the torso still within 5 mm over 1 s)
    filterTime = 0.3,        -- s: low-pass on the ZMP error, standing
    walkFilterTime = 1.0,    -- s: walking (two steps)
    minForce = 40.0,         -- N: a foot carries weight above this Fz (10% of the body's weight)
    sensorHeight = 0.106,    -- m: the sensor's origin (the ankle roll axis) above the sole
  },
  -- kick (Player/Motion/kick.lua): the OP3's structure with its distances scaled to the longer
  -- legs and its phases slowed to the drives' speeds. Not tuned and not a target: a 45 kg robot
  -- does not play KickSize football; kept so that the kick states have their data.
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
  -- stance and transitions
  tStance = 2.0,             -- s, to move into the stance from the current pose
  hardnessLegs = 1.0,
  hardnessArms = 1.0,
  hardnessHead = 1.0,
  hardnessHold = 1.0,         -- joints no motion state drives (the waist) when motion stiffens after relax
  -- fall detection (torso roll/pitch from the IMU)
  fallAngle = 0.5,           -- rad
  fallRate = 1.5,            -- rad/s together with fallAngleRate
  fallAngleRate = 0.3,       -- rad
  fallHardness = 0.15,       -- hardness while falling
  fallStillRate = 0.4,       -- rad/s: lying still below this (sum of |gyro|)
  fallSettleTime = 0.8,      -- s in falling before a stand-up
  fallStillTime = 0.3,       -- s lying still before a stand-up
  fallUprightAngle = 0.5,    -- rad: lying still with roll and pitch below this, the robot did not fall
  fallArms = { -1.2, 0.8 },  -- rad about the torso's y axis, both arms: falling forwards, backwards
  -- what a 45 kg robot does when it falls (Player/Motion/states/falling.lua): it cannot get up by
  -- itself and must not go limp (a limp fall folds the legs under 45 kg); it takes a protective
  -- pose held stiff enough to keep its shape: knees bent (the torso comes down lower, slower),
  -- elbows bent (the forearms take the ground before the head), the arms thrown towards the fall
  -- (fallArms); lying still it keeps holding the pose until someone puts it back on its feet.
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
  initialState = 'stance',   -- state the motion process starts in
}
