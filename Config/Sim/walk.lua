-- Walk parameters of the simulated OP3 (Player/Motion/walk.lua). Units: m, s, rad.
-- Changeable while the robot walks: Walk.set('name', value) from the REPL (one key, checked), or
-- edit this file and call Walk.reload(); the motion process applies either at its next tick.
return {
  -- timing
  tStep = 0.25,              -- s, one step
  tZmp = 0.165,              -- s, sqrt(COM height / g) of the linear inverted pendulum
  phSingle = { 0.1, 0.9 },   -- phase of the step where single support begins and ends
  -- posture
  bodyHeight = 0.25,         -- m, torso origin (hip yaw anchors, Config/Sim/robot.lua) above the ground
  bodyTilt = 0.08,           -- rad, torso pitch (forward positive)
  footX = 0.0,               -- m, trim of the torso origin behind the planned COM
  footY = 0.045,             -- m, half the lateral spacing of the feet (ankle points)
  supportX = 0.0,            -- m, ZMP in single support, ahead of the ankle
  supportY = 0.0,            -- m, ZMP in single support, outward from the ankle
  stepHeight = 0.035,        -- m, swing foot lift
  swingLead = 0.65,          -- fraction of single support in which the swing foot reaches its place
  -- velocity: limits and acceleration (per second)
  velLimitX = { -0.15, 0.40 },
  velLimitY = { -0.15, 0.15 },
  velLimitA = { -1.8, 1.8 },
  accLimit = { 0.4, 0.4, 2.0 },
  -- steps: swing foot relative to the support foot (y, a measured outward)
  stepLimitX = { -0.06, 0.11 },
  stepLimitY = { 0.08, 0.17 },
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
  -- kick (Player/Motion/kick.lua): phases reached one after the other, each over its duration.
  -- Tuned in the sim (Tests/motion/kick_trace.sh): the hip and knee run at the servos' speed limit
  -- through contact (toe ~1.8 m/s, ball ~1.8 m/s off the foot, ~1.1 m/s once rolling: ~1.2 m).
  -- A longer kick was found (Tests/motion/sim_walk_test.sh kick, random search over the swing):
  -- the same wind-up at x = 0.019, hip = 1.095, ankle = 0.283, then swing and follow-through with
  --   height = 0.023, tilt = -0.653, lean = 0.053, x = 0.135, z = 0.03, hip = -1.737, knee = -0.246,
  --   ankle = -1.359 (the support leg throws the torso back and forward while the kicking leg swings)
  -- sends the ball 2.1-2.3 m (left) and 2.3-2.8 m (right) over seeds and gaps 0.09-0.11 m, but the
  -- robot falls ~0.35 s after contact in every run: the swing spins it ~0.6 rad about the support
  -- foot (yaw) while the support knee locks straight, and no recovery phase tried caught it.
  kick = {
    supportY = 0.01,         -- m, COM over the support foot: outward from its ankle
    phases = {
      -- weight over the support foot, body a little higher
      { duration = 0.6, shift = 1, height = 0.005 },
      -- wind up: foot back and up, knee bent, toe down
      { duration = 0.3, shift = 1, height = 0.005, x = -0.015, z = 0.06, hip = 0.87, knee = 1.4, ankle = 0.4 },
      -- swing: a short phase, so the servos run at their speed limit (hip and knee together)
      { duration = 0.025, shift = 1, height = 0.005, tilt = 0.05, x = 0.095, z = 0.02, hip = -1.75, knee = 0.15,
        ankle = -0.5 },
      -- follow through
      { duration = 0.2, shift = 1, height = 0.005, tilt = 0.05, x = 0.095, z = 0.02, hip = -1.75, knee = 0.15,
        ankle = -0.5 },
      -- back, down, weight back to the middle
      { duration = 0.3, shift = 1, z = 0.03 },
      { duration = 0.3, shift = 1 },
      { duration = 0.5, shift = 0 },
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
