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
  -- arms: shoulder pitch, shoulder roll, elbow (joint angles of this robot)
  qLArm = { 0.0, -0.25, 0.0 },
  qRArm = { 0.0, 0.25, 0.0 },
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
    maxCorrection = 0.3,        -- rad, per joint
  },
  -- kick (Player/Motion/kick.lua): the body's and the kicking leg's phases side by side.
  -- Tuned in the sim (Tests/motion/kick_tune.sh: cross-entropy search over both feet, ball gaps
  -- 0.08/0.12 m and lateral offsets, penalised for a fall, a capture point beyond 5 cm of the
  -- support ankle and a turn; checked with Tests/motion/kick_sweep.sh): the hip, knee and ankle
  -- swing at the servos' speed limit while the torso leans back (0.34 rad over 0.17 s: the leg
  -- swings faster in the world) and both arms swing back against the torso's pitch momentum. The
  -- foot lifts before it draws back (dragging it turned the robot). The ball is met while the leg
  -- already heads for the return phase's targets, so those shape the strike too. Ball ~2.5 m/s
  -- off the foot, ~2.0 m/s 0.3 s later: 2.04-2.68 m (mean 2.39) over 90 kicks (5 seeds, gaps
  -- 0.08-0.12 m, lateral -0.03..+0.03 m), no fall. The servos' 4.8 rad/s is the limit: the toe
  -- meets the ball at ~2.1 m/s.
  kick = {
    supportY = 0.01,         -- m, COM over the support foot: outward from its ankle
    body = {
      -- weight over the support foot
      { duration = 0.6, shift = 1, height = -0.001, lean = -0.008 },
      { duration = 0.5, shift = 1, height = -0.001, lean = 0.0 },
      -- torso back, arms back, through the swing
      { duration = 0.2, shift = 1, height = 0.01, lean = -0.02, tilt = -0.15, arms = 0.2 },
      -- upright again, then the weight back to the middle
      { duration = 0.35, shift = 1, lean = 0.01 },
      { duration = 0.35, shift = 1 },
      { duration = 0.5, shift = 0 },
    },
    leg = {
      { duration = 0.6 },
      -- lift, then wind up: foot back and up, knee bent, toe down
      { duration = 0.1, z = 0.03 },
      { duration = 0.35, x = -0.015, z = 0.045, hip = 0.5, knee = 1.2, ankle = 0.4, arm = 0.3 },
      -- swing: a short phase, so the servos run at their speed limit; follow through
      { duration = 0.04, x = 0.07, z = 0.02, hip = -1.2, knee = 0.0, ankle = 0.2, arm = 0.2 },
      { duration = 0.1, x = 0.07, z = 0.02, hip = -1.2, knee = 0.0, ankle = 0.2, arm = 0.2 },
      -- back, down
      { duration = 0.4, x = -0.025, z = 0.035, hip = 0.05, knee = -0.03, ankle = -0.03 },
      { duration = 0.35 },
      { duration = 0.5 },
    },
  },
  -- stance and transitions
  tStance = 1.0,             -- s, to move into the stance from the current pose
  hardnessLegs = 1.0,
  hardnessArms = 0.5,
  hardnessHead = 0.5,
  -- fall detection (torso roll/pitch from the IMU)
  fallAngle = 0.6,           -- rad
  fallRate = 2.5,            -- rad/s together with fallAngleRate
  fallAngleRate = 0.35,      -- rad
  fallHardness = 0.15,       -- hardness while falling (soft)
  fallStillRate = 0.4,       -- rad/s: lying still below this (sum of |gyro|)
  fallSettleTime = 0.8,      -- s in falling before a stand-up
  initialState = 'stance',   -- state the motion process starts in
}
