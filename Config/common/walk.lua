-- The walk's parameters (Player/Motion/walk.lua and the motion states), every key once, with its
-- default. Units: m, s, rad. A body's Config/robots/<ROBOT>/walk.lua holds only what differs.
-- The defaults are the OP3's where a value depends on the body (the OP3 is the default ROBOT);
-- a feature only some bodies have is off here (0, or `false`: see Lib/Config.lua).
-- Changeable while the robot walks: param('walk.<key>', value) from the REPL (Lib/param.lua:
-- every process that uses the walk takes it at its next tick; param.save() writes it into the
-- layer file it came from). Walk.set('<key>', value) and Walk.reload() (Lib/Walk.lua, through the
-- motion process only) do the same for the walk alone.
return {
  -- timing
  tStep = 0.25,              -- s, one step
  tZmp = 0.165,              -- s, sqrt(COM height / g) of the linear inverted pendulum
  phSingle = { 0.1, 0.9 },   -- phase of the step where single support begins and ends
  -- engine (read at the motion process's start): 'analytic', the COM solved step by step
  -- (Player/Motion/walk.lua), or 'preview', ZMP preview control over the planned steps
  -- (Player/Motion/walk_preview.lua: window in s, weights of the ZMP error and the COM jerk, lead-in s)
  engine = 'analytic',
  preview = { window = 1.6, Qe = 1.0, R = 1e-6, lead = 0.4 },
  -- step adjustment (capture point, Player/Motion/step_adjust.lua): the swing foot lands gain x the
  -- capture point's error beyond the dead band (m) further, at most max (m), within the step limits
  -- (moved while it travels, until `retarget` of its way: beyond it the foot would have to jump);
  -- a sideways error beyond switchError (m) at a step's start swings the foot on the push's side;
  -- beyond touchdownError (m) a swing foot on the far side is put down within touchdownTime (s)
  -- and the step ends; the swing foot's ankle turns against the torso's tilt (IMU) by level
  -- (fraction: roll, pitch) so that it lands flat, faded over levelTime (s) once it carries.
  -- gain = 0: off.
  -- The capture point's error from the IMU (Player/Motion/capture.lua): velocityLeak (s) > 0 adds
  -- the accelerometer's velocity (a shove moves the body before it tips it; 0: the tilt and its
  -- rate alone). The activation gates feedback.capture/captureHip and the landing by the error's
  -- size: 0 below activateFrom (m, { x, y }), 1 beyond activateFull (0: no gate, always 1), held
  -- after a push and fading over activateHold (s).
  stepAdjust = { gain = 0, deadband = { 0.01, 0.01 }, max = { 0.05, 0.08 }, switchError = 0.03,
    touchdownError = 0.04, touchdownTime = 0.05, level = { 1.0, 1.0 }, levelTime = 0.15, velocityLeak = 0,
    retarget = 0.85, activateFrom = { 0, 0.03 }, activateFull = { 0, 0 }, activateHold = 1.0 },
  -- posture
  bodyHeight = 0.25,         -- m, torso origin (between the hip yaw joints: the URDF's body_link) above the ground
  bodyTilt = 0.08,           -- rad, torso pitch (forward positive)
  footX = 0.0,               -- m, trim of the torso origin behind the planned COM
  footY = 0.045,             -- m, half the lateral spacing of the feet (ankle points)
  supportX = 0.0,            -- m, ZMP in single support, ahead of the ankle
  supportY = 0.0,            -- m, ZMP in single support, outward from the ankle
  -- the soles, for the gap a turned foot keeps from the other (Player/Motion/walk.lua clear_feet):
  -- { toe, heel = m ahead of and behind the ankle point, inner = m from it to the inner edge };
  -- false: not checked. footClearance: m, that gap
  sole = false,
  footClearance = 0.01,
  stepHeight = 0.035,        -- m, swing foot lift
  -- turning (Player/Motion/walk.lua step_target, step_period, lead_hip_yaw): the feet turn by
  -- stepLimitA per step at most, so the closing foot lands toed in by turnToeIn (0..1) x a step's
  -- turn (the feet's relative yaw swings about zero, not from zero to twice it); a fast turn takes
  -- shorter steps (turnStep = { tStep = s, va = { lo, hi } rad/s }: tStep from the walk's at va[1]
  -- to turnStep's at va[2]; false: every step tStep); hipYawLead (s): the hip yaw servos' lag made
  -- up (the command leads the plan by it x its rate)
  turnToeIn = 0,
  turnStep = false,
  hipYawLead = 0,            -- s
  -- the swing foot turns over all of single support at a near-constant rate, ramps of this
  -- fraction at either end (false: it turns with the step's ground motion)
  swingYawRamp = false,
  swingLead = 0.65,          -- fraction of single support in which the swing foot reaches its place
  swingDelay = 0.0,          -- fraction of single support the swing foot lifts before it moves
  -- velocity: limits and acceleration (per second)
  velLimitX = { -0.15, 0.40 },
  velLimitY = { -0.15, 0.15 },
  velLimitA = { -2.2, 2.2 },
  accLimit = { 0.4, 0.4, 2.0 },
  -- steps: swing foot relative to the support foot (y, a measured outward)
  stepLimitX = { -0.06, 0.11 },
  stepLimitY = { 0.08, 0.17 },
  stepLimitA = { -0.5, 0.5 },
  -- arms, by joint name (Player/Motion/walk.lua, kick.lua, states/falling.lua): each side's posture
  -- while standing, walking and kicking (the joints named here are the ones the walk drives), and
  -- the joints that turn the arm about the torso's y axis (`pitch`: arm swing, gyro feedback, the
  -- kick's and the fall's arm motions) and x axis (`roll`: gyro feedback):
  -- { l = { posture = { joint = rad, ... }, pitch = joint, roll = joint }, r = ... } (pitch, roll:
  -- false when left out). Joint names are the body's, so the default is a body without arms.
  arms = {},
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
    -- rad per rad of the IMU's torso tilt (roll, pitch - bodyTilt) on the ankles: off, as the
    -- obstacle scenario's walker with it does not reach the ball (docs/results/tuning.md)
    tilt = { 0, 0 },
    tiltTimeConstant = 0.05,    -- s, low-pass on that tilt
    -- rad per m of the capture point's error (Player/Motion/capture.lua) on the ankles and the hips
    -- ({ roll, pitch }), while stepping, beyond stepAdjust's dead band, times its activation: off
    -- (the push figures with them on: docs/results/tuning.md)
    capture = { 0, 0 },
    captureHip = { 0, 0 },
    maxCorrection = 0.3,        -- rad, per joint
  },
  -- balance on the ankle F/T sensors (Player/Motion/balance.lua): off (zmpGain = 0) on a body
  -- without F/T sensors (a sim's ft slots are the simulator's instruments only); the other numbers
  -- are the body's, for a run with it switched on in the sim (param('walk.balance.zmpGain', { 2, 2 }))
  balance = {
    zmpGain = { 0.0, 0.0 },  -- 1/s, standing, { x, y }: COM shift rate per m of ZMP error; 0 off
    walkGain = { 0.0, 0.0 }, -- 1/s, walking (the step's ZMP swing filtered out: walkFilterTime)
    leakTime = 2.0,          -- s: the shift decays with this time constant
    maxShift = 0.01,         -- m, per axis
    maxRate = 0.01,          -- m/s: the shift moves no faster (a short push: balance.lua)
    filterTime = 0.3,        -- s: low-pass on the ZMP error, standing
    walkFilterTime = 1.0,    -- s: walking (two steps)
    minForce = 3.0,          -- N: a foot carries weight above this Fz (10% of the body's weight)
    sensorHeight = 0.0305,   -- m: the sensor's origin (the ankle roll axis) above the sole
  },
  -- kick (Player/Motion/kick.lua): the body's and the kicking leg's phases side by side (durations
  -- in s; shift: fraction of the way over the support foot; height, lean, x, z in m; tilt, arms,
  -- hip, knee, ankle, arm in rad; a field a phase leaves out is 0). The OP3's, tuned in the sim
  -- (Tools/tune/kick_tune.sh): the hip, knee and ankle swing at the servos' speed limit while the
  -- torso leans back (the leg swings faster in the world) and both arms swing back against the
  -- torso's pitch momentum; the foot lifts before it draws back (dragging it turns the robot); the
  -- ball is met while the leg already heads for the return phase's targets, so those shape the
  -- strike too.
  kick = {
    supportY = 0.01,         -- m, COM over the support foot: outward from its ankle
    body = {
      -- weight over the support foot
      { duration = 0.45, shift = 1, height = -0.001, lean = -0.008 },
      { duration = 0.5228, shift = 1, height = -0.001, lean = 0.002 },
      -- torso back, arms back, through the swing
      { duration = 0.1654, shift = 1, height = 0.0202, lean = -0.0425, tilt = -0.3391, arms = 0.4021 },
      -- upright again, then the weight back to the middle
      { duration = 0.35, shift = 1, lean = 0.023 },
      { duration = 0.327, shift = 1 },
      { duration = 0.45, shift = 0 },
    },
    leg = {
      { duration = 0.45 },
      -- lift, then wind up: foot back and up, knee bent, toe down
      { duration = 0.0919, z = 0.0383 },
      { duration = 0.3288, x = -0.0198, z = 0.0596, hip = 0.7011, knee = 1.4806, ankle = 0.4798, arm = 0.3503 },
      -- swing: a short phase, so the servos run at their speed limit; follow through
      { duration = 0.0372, x = 0.0923, z = 0.0261, hip = -1.7574, knee = 0.0013, ankle = 0.217, arm = 0.2423 },
      { duration = 0.0931, x = 0.0923, z = 0.0261, hip = -1.7574, knee = 0.0013, ankle = 0.217, arm = 0.2423 },
      -- back, down
      { duration = 0.3819, x = -0.0323, z = 0.0456, hip = 0.0678, knee = -0.0413, ankle = -0.0335 },
      { duration = 0.3 },
      { duration = 0.45 },
    },
  },
  -- kicks out of the walk (Player/Motion/walk_kick.lua): { expire = s a request waits for its step,
  -- maxSpeed = { m/s, m/s, rad/s } the walk's at most at the kick step's start, forward = {...},
  -- side = {...} } (the keys of each kind: Config/robots/op3/walk.lua; ballMax false when left out, a
  -- phase's fields 0); false: the body has none
  walkKick = false,
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
  -- what the body does when it falls (Player/Motion/states/falling.lua): false: go soft
  -- (fallHardness) and stand up; or { standup = false, pose = { joint = rad }, hardness = 0..1,
  -- rest = 'hold' | 'release' } for a body that cannot get up by itself
  fallPolicy = false,
  initialState = 'stance',   -- state the motion process starts in
}
