-- Walk parameters of the DARwIn-OP (Player/Motion/walk.lua). Units: m, s, rad.
-- Starting point: the OP3's (Config/robots/op3/walk.lua) with the posture and step limits scaled to
-- the DARwIn-OP's shorter legs (hip 0.2195 m above the soles against 0.25) and narrower hips (0.037 m).
-- Changeable while the robot walks: Walk.set('name', value) from the REPL (one key, checked), or
-- edit this file and call Walk.reload(); the motion process applies either at its next tick.
return {
  -- timing
  tStep = 0.25,              -- s, one step
  tZmp = 0.155,              -- s, sqrt(COM height / g) of the linear inverted pendulum
  phSingle = { 0.1, 0.9 },   -- phase of the step where single support begins and ends
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
  bodyHeight = 0.225,         -- m, torso origin (hip yaw anchors, Config/Sim/robot.lua) above the ground
  bodyTilt = 0.08,           -- rad, torso pitch (forward positive)
  footX = 0.0,               -- m, trim of the torso origin behind the planned COM
  footY = 0.037,             -- m, half the lateral spacing of the feet (ankle points)
  supportX = 0.0,            -- m, ZMP in single support, ahead of the ankle
  supportY = 0.0,            -- m, ZMP in single support, outward from the ankle
  stepHeight = 0.03,        -- m, swing foot lift
  swingLead = 0.65,          -- fraction of single support in which the swing foot reaches its place
  -- velocity: limits and acceleration (per second)
  velLimitX = { -0.12, 0.30 },
  velLimitY = { -0.12, 0.12 },
  velLimitA = { -1.8, 1.8 },
  accLimit = { 0.4, 0.4, 2.0 },
  -- steps: swing foot relative to the support foot (y, a measured outward)
  stepLimitX = { -0.05, 0.09 },
  stepLimitY = { 0.074, 0.14 },
  stepLimitA = { -0.05, 0.95 },
  -- arms, by joint name (Player/Motion/walk.lua, kick.lua, states/falling.lua): each side's posture
  -- while standing, walking and kicking (the joints named here are the ones the walk drives), and
  -- the joints that turn the arm about the torso's y axis (`pitch`: arm swing, gyro feedback, the
  -- kick's and the fall's arm motions) and x axis (`roll`: gyro feedback). A body without arms: {}.
  arms = {
    l = { posture = { l_sho_pitch = 0.0, l_sho_roll = -0.25, l_el = 0.0 }, pitch = 'l_sho_pitch', roll = 'l_sho_roll' },
    r = { posture = { r_sho_pitch = 0.0, r_sho_roll = 0.25, r_el = 0.0 }, pitch = 'r_sho_pitch', roll = 'r_sho_roll' },
  },
  armSwing = 0.0,            -- rad of arm pitch per m of foot lead
  hipRollCompensation = 0.0, -- rad, support hip roll added in single support
  -- heading: the IMU's yaw follows the integral of the commanded turning rate
  headingGain = 1.0,         -- rad/s of extra turning per rad of heading error
  headingMaxCorrection = 0.3,-- rad/s
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
    maxCorrection = 0.3,        -- rad, per joint
  },
  -- balance on the ankle F/T sensors (Player/Motion/balance.lua): off (zmpGain = 0): the real DARwIn-OP
  -- has no F/T sensors (its sim's ft slots are the simulator's instruments only); the other numbers
  -- are the body's, for a run with it switched on in the sim (Walk.set('balance.zmpGain', { 2, 2 }))
  balance = {
    zmpGain = { 0.0, 0.0 },  -- 1/s, standing, { x, y }: COM shift rate per m of ZMP error; 0 off
    walkGain = { 0.0, 0.0 }, -- 1/s, walking (the step's ZMP swing filtered out: walkFilterTime)
    leakTime = 2.0,          -- s: the shift decays with this time constant
    maxShift = 0.01,         -- m, per axis
    maxRate = 0.01,          -- m/s: the shift moves no faster (a short push: balance.lua)
    filterTime = 0.3,        -- s: low-pass on the ZMP error, standing
    walkFilterTime = 1.0,    -- s: walking (two steps)
    minForce = 3.0,          -- N: a foot carries weight above this Fz (10% of the body's weight)
    sensorHeight = 0.0335,   -- m: the sensor's origin (the ankle roll axis) above the sole
  },
  -- kick (Player/Motion/kick.lua): the body's and the kicking leg's phases side by side; the
  -- OP3's structure (torso back and arms back through a short swing at the servos' speed limit, the
  -- foot lifted before it draws back, the ball met while the leg heads for the return phase's
  -- targets), retuned for this body in the sim (Tools/tune/kick_tune.sh, ROBOT=darwin: 8
  -- generations from the OP3-derived set, then 6 more at spread 0.6; both feet, ball gaps 0.08/0.12 m,
  -- lateral +-0.025 m, penalised for a fall, a capture point beyond 5 cm and a turn): 1.28-1.45 m
  -- over the tuner's 6 kicks (was 0.9-1.4), 1.30-1.38 m in the kick scenario (seeds 1-3), no fall.
  -- The MX-28's 5.24 rad/s limits the toe to ~1.7 m/s at the ball.
  kick = {
    supportY = 0.01,         -- m, COM over the support foot: outward from its ankle
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
  -- stance and transitions
  tStance = 1.0,             -- s, to move into the stance from the current pose
  hardnessLegs = 1.0,
  hardnessArms = 0.5,
  hardnessHead = 0.5,
  hardnessHold = 1.0,         -- joints no motion state drives (a waist) when motion stiffens after relax
  -- fall detection (torso roll/pitch from the IMU)
  fallAngle = 0.6,           -- rad
  fallRate = 2.5,            -- rad/s together with fallAngleRate
  fallAngleRate = 0.35,      -- rad
  fallHardness = 0.15,       -- hardness while falling (soft)
  fallStillRate = 0.4,       -- rad/s: lying still below this (sum of |gyro|)
  fallSettleTime = 0.8,      -- s in falling before a stand-up
  fallStillTime = 0.3,       -- s lying still before a stand-up
  fallUprightAngle = 0.5,    -- rad: lying still with roll and pitch below this, the robot did not fall
  fallArms = { -1.2, 0.8 },  -- rad about the torso's y axis, both arms: falling forwards, backwards
  initialState = 'stance',   -- state the motion process starts in
}
