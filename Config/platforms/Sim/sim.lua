-- The simulated world (read by the sim DCM, Platforms/Sim; the bodies are Config/robots/*). SI units, radians.
-- Field frame: origin at the centre spot, x towards the goal at +x, z up.
return {
  physics = {
    timestep = 0.001,            -- s; the control period (robot.lua) must be a multiple of it
    iterations = 20,             -- dWorldQuickStep iterations
    gravity = 9.81,
    -- Rotor-like inertia added to every moving link's inertia diagonal, kg*m^2 (shared/robots/README.md:
    -- QuickStep needs 3e-4..1e-3 on the 12 g links; the real servos' reflected rotor inertia is larger).
    link_rotor_inertia = 5e-4,
    -- rad: in torque mode a joint's gear friction holds the joint where it stuck until it has given
    -- this much (then it slips and the stuck place follows): a harmonic drive's lost motion, at most
    -- 1 arc-minute in the makers' catalogues (no figure in shared/robots; the small bodies have no
    -- torque path). Platforms/Sim/world_step.cpp, servo_update.
    gear_presliding = 2.9e-4,
    linear_damping = 0,          -- no air drag on links (a 3 kg robot is not slowed by air)
  },

  -- Position servos: each joint is driven by its own actuator model (robot.lua `actuator`, the models
  -- in Config/common/actuators.lua): an ODE hinge velocity motor, target velocity = gain * (command -
  -- position), clamped to the joint's velocity limit (URDF), with at most hardness * torque limit
  -- (URDF effort) to reach it; torque off: the URDF's damping and friction.
  servo = {
    temperature = 40,            -- deg C reported
  },

  contact = {
    mu = 1.0,                    -- robot-carpet friction
    kp = 5e4,                    -- N/m per contact point
    kd = 300,                    -- N*s/m per contact point
    max_contacts = 8,            -- per geom pair
    robot_mu = 0.5,              -- robot-robot, robot-goal
  },

  imu = {
    gyro_noise = 0.002,          -- rad/s, standard deviation
    accel_noise = 0.02,          -- m/s^2, standard deviation
  },

  -- RoboCup Humanoid KidSize field
  field = {
    length = 9.0, width = 6.0,
    border = 1.0,                -- carpet outside the lines on every side
    line_width = 0.05,
    centre_circle_diameter = 1.5,
    goal_area_length = 1.0, goal_area_width = 3.0,
    penalty_area_length = 2.0, penalty_area_width = 5.0,
    penalty_mark_distance = 1.5, penalty_mark_size = 0.1,
  },
  goal = {
    width = 2.6,                 -- inner distance between the posts
    height = 1.2,                -- underside of the crossbar
    depth = 0.6,
    post_diameter = 0.1,
  },
  ball = {
    diameter = 0.14,             -- FIFA size 1
    mass = 0.2,                  -- kg
    mu = 0.6,                    -- ball-carpet sliding friction
    -- rolling resistance of artificial turf (ODE rho, m: resisting torque = rolling * normal force);
    -- for a hollow ball the deceleration is 3 * rolling * g / (5 * r) = 0.59 m/s^2, plus air drag:
    -- a ball released at 3 m/s rolls about 7 m, as in the FIFA turf roll test (4-10 m)
    rolling = 0.007,
    bounce = 0.5,                -- restitution on the carpet, posts and robots
    start = { 0, 0 },
    -- how the camera sees it: 'white' (today's Humanoid League ball: white with a dark patch
    -- around each of the 12 pentagon centres of a truncated icosahedron, turning with the ball) or
    -- 'orange' (plain, the seed's ball, which the colour-table vision finds)
    kind = 'orange',
  },

  -- Team colours as the cameras see them: each robot's torso (its root link) wears its team's jersey.
  teams = {
    -- Y, U, V (BT.601 full range, as the camera's frames) of team 1 and team 2: red (RGB 200, 30, 45)
    -- and blue (RGB 30, 70, 190), the Humanoid League's usual pair. The red keeps U >= 104, clear of
    -- the orange ball's U (52) and of the colour table's orange box (Config/common/vision.lua).
    colours = { { 83, 107, 212 }, { 72, 195, 98 } },
    -- the team (1 or 2) of each robot in the order of --robots; robots beyond the list: the first
    -- half of the world's robots team 1, the rest team 2 (as Tools/match/match.sh gives them out)
    of_robot = {},
  },

  -- the simulated camera: size, rate and field of view are the body's (Config/robots/<ROBOT>/camera.lua),
  -- its pose the description's camera frame; here what only the simulation adds
  camera = {
    frame = 'camera_link',       -- URDF frame: x along the optical axis, z image-up
    latency_ticks = 4,           -- a frame exposed at tick N is delivered with sensor tick N + 4 (32 ms)
    noise = 2,                   -- the clean camera's luma noise (standard deviation, grey levels)
    -- The camera's imperfections (Platforms/Sim/effects.h): true in every sim run and scenario test;
    -- false: the clean camera (flat light, only the luma noise above) for exact regression tests.
    -- The lens's distortion (the body's camera.lua calibration) is drawn either way: it is the
    -- camera's geometry, which the vision undoes, not a disturbance. Deterministic for a seed.
    realism = true,
    -- s the shutter is open: the image smears along the camera's motion from the pose at its start
    -- to the one at its end (head and body). 10 ms: a C920 at exposure_absolute 100 (units of
    -- 100 us), a usual fixed indoor setting that keeps the gain low; darker halls need longer.
    exposure = 0.010,
    -- sensor noise after the camera's own processing (grey levels, standard deviation): luma at
    -- mid-grey 128, growing with the square root of the signal (shot noise), and chroma. A C920 in a
    -- lit hall measures ~2-3 in luma on a flat grey card; chroma less, the UV planes being averaged
    -- over two pixels.
    noise_luma = 3.0,
    noise_chroma = 2.0,
    -- exposure and white balance drift over time with fixed camera settings (the light changes:
    -- daylight through windows, lamps warming up): relative amplitude of the brightness, of the red
    -- and blue gains, and the slower period in s (a second one at period / 2.71)
    gain_drift = 0.06,
    wb_drift = 0.03,
    drift_period = 20,
    -- uneven light: the illumination changes by this fraction across the carpet's half-diagonal
    -- (a seeded direction; the HL asks for no particular light, halls vary by 20-30% over a field)
    light_gradient = 0.10,
    -- soft shadows of the hall's overhead lights: the darkening at the centre of a shadow under a
    -- robot's torso (Gaussian, standard deviation shadow_robot_radius m) and under the ball (a
    -- contact shadow, 0.7 ball radii)
    shadow_robot = 0.35,
    shadow_robot_radius = 0.12,
    shadow_ball = 0.5,
  },

  -- Start poses of the robots in the order of --robots (x, y, yaw); more robots wrap around.
  start = {
    { -1.0, 0.0, 0.0 },
    { 1.0, 0.0, math.pi },
    { -2.0, 1.5, 0.0 },
    { 2.0, -1.5, math.pi },
  },

  -- Static boxes on the carpet (terrain: a step, a ramp), none on the match field. Each
  -- { pos = {x, y, z} centre, size = {sx, sy, sz}, rpy = {roll, pitch, yaw} }, m and rad; they collide
  -- with the carpet's friction and stiffness (contact) and the camera sees them. The walking tests
  -- put theirs in through a site overlay (Tests/motion/terrain.lua: a 1 cm step, a 5 degree ramp).
  objects = {},

  fall_angle = 1.0,              -- rad of torso tilt beyond which the robot counts as fallen
  watchdog = 0.5,                -- s of robot time without tick_ack before holding the pose (real time)
  -- A writer that stopped (SIGSTOP, a debugger), vanished or loops without acknowledging is as
  -- dangerous as a dead one: after `stall_cycles` DCM cycles without a new tick_ack the DCM looks at
  -- the process (/proc) and goes safe at once. 2, not 1: one late answer is routine on a loaded
  -- machine. A writer that merely was not scheduled burns no CPU and is left to `watchdog` (a busy
  -- machine must not make the robot go limp); one that burnt more than `stall_cpu` s of CPU since
  -- its last tick_ack is looping: a tick of motion takes under 1 ms of CPU (1.4 ms at most measured
  -- over a minute of play: 7000 ticks).  3 ms: twice that, yet a loop that gets a fifth of a CPU trips
  -- within the 2 cycles.
  stall_cycles = 2,
  stall_cpu = 0.003,
  safe_hardness = 0.3,           -- the held pose's hardness after a watchdog trip (as on the OP platform)
  start_hardness = 1.0,          -- every start: each joint holds its present pose at this hardness, torque on
  battery = 12.0,                -- V
}
