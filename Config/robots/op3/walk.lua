-- The OP3's walk: what differs from Config/common/walk.lua (every key is documented there; the
-- defaults are the OP3's posture, limits, feedback and kick). The measurements behind these
-- values, and the commands that take them: docs/results/tuning.md, section "OP3: walk".
return {
  -- the capture point's step adjustment on (sideways pushes), its dead band keeping the walk's own
  -- sway out of the landing; switching the swing foot, early touchdowns and landing levelling
  -- measure worse on this body (a loaded foot cannot lift): off (switchError and touchdownError
  -- 1 m, out of reach; level 0)
  stepAdjust = { gain = 1.0, deadband = { 0.03, 0.02 }, switchError = 1, touchdownError = 1, level = { 0, 0 } },
  -- the soles (shared/robots/op3_reference.txt: 0.127 x 0.078 m, centre 1.3 cm outward of the
  -- ankle point)
  sole = { toe = 0.0635, heel = 0.0635, inner = 0.026 },
  -- turning: the legs touch (op3.urdf's boxes: hip roll links, knees) once the feet's relative yaw
  -- passes 0.52 rad toed out or 0.45 toed in at the stance's spacing (Tools/tune/hip_yaw_clearance.py):
  -- stepLimitA (the default) keeps within it, the closing foot lands fully toed in, and beyond
  -- 1.5 rad/s the steps shorten to 0.2 s at 2.0 rad/s rather than turn further
  turnToeIn = 1.0,
  turnStep = { tStep = 0.2, va = { 1.5, 2.0 } },
  -- s: the XM430's lag (the sim's servo: time constant 1 / 30 s from Config/common/actuators.lua,
  -- plus one 8 ms tick before a command acts)
  hipYawLead = 0.041,
  -- the swing foot turns at a near-constant rate: with the step's own profile a 1 rad turn (2 rad/s)
  -- asks the hip yaw for 12 rad/s, the XM430 gives 4.8
  swingYawRamp = 0.2,
  arms = {
    l = { posture = { l_sho_pitch = 0.0, l_sho_roll = -0.25, l_el = 0.0 }, pitch = 'l_sho_pitch', roll = 'l_sho_roll' },
    r = { posture = { r_sho_pitch = 0.0, r_sho_roll = 0.25, r_el = 0.0 }, pitch = 'r_sho_pitch', roll = 'r_sho_roll' },
  },
  -- kicks out of the walk (Player/Motion/walk_kick.lua): the kicking foot's swing on a longer step,
  -- the COM plan and the support foot walking on. Per kind: the step (tStep s, phSingle), the
  -- nominal ball (x, y m from the support ankle, y outward of the foot's line), ballMax (m: a ball
  -- further ahead at the kick step's start waits for the foot's next step, as the swing's way-points
  -- are clamped to the leg's reach and the foot would meet it slowing down), the contact point, the
  -- reach of the way-points (m), the support foot's offset, and the swing's phases (way-points
  -- relative to the contact point; hip, knee, ankle, arm, tilt, arms in rad). The foot's striking
  -- face from the URDF's sole plate (l_ank_roll_link): its front 0.063 m ahead of the sole point,
  -- its outer edge 0.052 m outward; the ball's radius 0.07 m, met about 0.06 m above the ground.
  -- The strike is a short phase, so the servos run at their speed limit (4.8 rad/s) through it.
  -- Both kinds come from the cross-entropy search of Tools/tune/walk_kick_tune.sh.
  walkKick = {
    expire = 2.0,            -- s: two step pairs at 0.08 m/s
    maxSpeed = { 0.15, 0.04, 0.3 }, -- tuned at 0.12 m/s straight; out of a 0.25 m/s walk the kick falls
    forward = {
      tStep = 0.54, phSingle = { 0.06, 0.94 },
      ball = { x = 0.21, y = 0.013 },
      ballMax = 0.145,
      contact = { x = 0.13, y = 0.013 },
      reach = { x = { -0.0303, 0.123 }, y = { 0.07, 0.16 } },
      support = { x = -0.0116, y = 0.0198 },
      phases = {
        { duration = 0.05, x = -0.1, z = 0.04 },
        { duration = 0.1373, x = -0.2, z = 0.0338, hip = -0.1552, knee = 0.0, ankle = -0.0738, arm = 0.3 },
        { duration = 0.024, x = 0.121, z = 0.0843, hip = -0.4598, knee = -0.7108, ankle = -0.3959, arm = 0.2,
          tilt = -0.3246, arms = 0.2776 },
        { duration = 0.0676, x = 0.121, z = 0.0843, hip = -0.4598, knee = -0.7108, ankle = -0.3959,
          arm = 0.2, tilt = -0.3246, arms = 0.2776 },
        { duration = 0.1364, x = -0.04, z = 0.045 },
      },
    },
    side = {
      tStep = 0.56, phSingle = { 0.08, 0.92 },
      ball = { x = 0.05, y = 0.13 },
      ballMax = 0.0755,
      contact = { x = 0.0118, y = 0.12 },
      reach = { x = { -0.0971, 0.1167 }, y = { 0.07, 0.2 } },
      support = { x = -0.002, y = 0.0022 },
      phases = {
        { duration = 0.06, y = -0.02, z = 0.04 },
        { duration = 0.1351, y = -0.06, z = 0.0464, hip = 0.2618, hipRoll = -0.1101, knee = 0.0, ankle = -0.1058 },
        { duration = 0.0434, y = 0.049, z = 0.0562, hip = -0.4019, hipRoll = 0.5134, knee = 0.0, ankle = 0.1045,
          tilt = -0.0408, arms = 0.0492 },
        { duration = 0.0646, y = 0.049, z = 0.0562, hip = -0.4019, hipRoll = 0.5134, knee = 0.0, ankle = 0.1045,
          tilt = -0.0408, arms = 0.0492 },
        { duration = 0.1077, y = 0.0, z = 0.04 },
      },
    },
  },
}
