-- Actuator models: what a joint's servo can do. A robot names one per joint in robot.lua
-- (`actuator = { l_knee = 'MX-28', ... }`); a robot with a servo not listed here adds its model in
-- Config/robots/<robot>/actuators.lua (same fields). Used by:
--   Tools/urdf/gen_urdf.py   writes torque, speed, damping and friction into the robot's URDF (<limit>
--                     effort/velocity, <dynamics> damping/friction), so the URDF carries them;
--   the sim (Platforms/Sim/world_step.cpp) drives each joint as an ODE hinge velocity motor:
--                     target speed = gain * (command - position), clamped to the URDF velocity,
--                     at most hardness * URDF effort of torque; torque off: URDF damping/friction;
--                     positions quantised to `resolution`, speeds to `speed_unit` (world_sense.cpp).
-- Fields (SI units):
--   torque      N*m, stall torque at the robot's supply voltage (URDF effort)
--   speed       rad/s, no-load speed at that voltage (URDF velocity)
--   p_gain      the servo's default position P gain register value, and `stiffness` (N*m/rad) what
--   stiffness   it amounts to at the joint (documentation: the sim uses `gain`)
--   gain        1/s, the sim's velocity-motor gain: stiffness / (torque / speed), i.e. K/b with b the
--               back-EMF damping of a DC motor
--   resolution  encoder counts per turn
--   speed_unit  rad/s per count of the present-speed register
--   damping     N*m*s/rad, back-drive damping with the torque off
--   friction    N*m, back-drive friction with the torque off
local rpm = 2 * math.pi / 60

-- The Hubo2+'s joint drives (Config/robots/hubo2plus; shared/robots/hubo_reference.txt): a brushed DC
-- motor on a JMC board, belt or spur stage and harmonic drive. The reference has each joint's
-- total reduction and encoder counts (ACTUATORS) but no motor data: no public source reached gives
-- the motors' power, torque constant or speed. Chosen, conservatively, and said so here:
--   torque  the openHubo model's per-joint caps (hubo_reference.txt LIMITS, "maxtorque": 95 N*m hip
--           roll/pitch and knee, 71 hip yaw, ankles and waist, 35/25 shoulder, 25 elbow, 9 wrist,
--           2.7 neck) as the peak joint torque: simulation settings, not measured; for a 45 kg
--           robot they leave a wide margin on quasi-static loads (about 20 N*m at a knee in a squat)
--           and are below what a 100-200 W motor through 160:1-500:1 would give at stall;
--   speed   the motor's no-load speed taken as 6000 rpm (below the 7000-10000 rpm of the 24-48 V
--           100-200 W class motors) divided by the joint's reduction: 2.5 rad/s at 250:1 up to
--           6.3 rad/s at 100:1, all below HuboCan's software limit of 6-7 rad/s (LIMITS v_max);
--   gain    30/s, the loop gain of the other models (the JMC's PD gains are not public): stiffness
--           gain * torque / speed, about 900 N*m/rad at a hip pitch;
--   damping torque off: b = torque / speed, as the other models; friction: a harmonic drive's
--           back-drive torque, 2 N*m on the legs and waist, 1 on the arms, 0.1 on the neck (chosen);
--   resolution  the joint's encoder counts per turn (ACTUATORS counts_per_joint_rev); speed_unit one
--           count per 5 ms cycle (the DCM differentiates the encoder at 200 Hz; no speed register).
local function hubo_drive(ratio, torque, counts, friction)
  local speed = math.floor(6000 * rpm / ratio * 1000 + 0.5) / 1000   -- rad/s, to 3 decimals
  return {
    torque = torque,
    speed = speed,
    p_gain = 0,                  -- no position-gain register (the JMC's gains are not public)
    stiffness = 30 * torque / speed,
    gain = 30,
    resolution = counts,
    speed_unit = 2 * math.pi / counts / 0.005,
    damping = math.floor(torque / speed * 1000 + 0.5) / 1000,
    friction = friction,
  }
end

return {
  -- ROBOTIS Dynamixel XM430-W350 (OP3), numbers of shared/robots/op3_reference.txt's servo model
  -- (MuJoCo Menagerie robotis_op3: kp 21.1 N*m/rad, torque limit 5 N*m, damping 1.084 N*m*s/rad,
  -- friction loss 0.03 N*m). The datasheet gives 4.1 N*m stall and 46 rpm at 12 V: the 5 N*m limit
  -- is above that stall torque; it is what the OP3's walk and kick were tuned with (unchanged here).
  -- gain 30/s is the sim's tuned loop gain (21.1 / 1.04 = 20/s by the K/b rule).
  ['XM430-W350'] = {
    torque = 5.0,
    speed = 4.82,                -- 46 rpm at 12 V
    p_gain = 800,                -- Position P Gain register default
    stiffness = 21.1,
    gain = 30,
    resolution = 4096,
    speed_unit = 0.229 * rpm,
    damping = 1.084,
    friction = 0.03,
  },
  -- ROBOTIS Dynamixel MX-28T (DARwIn-OP) at the robot's 11.1 V 3-cell LiPo (shared/robots/
  -- darwin_reference.txt, SERVO): stall 2.3 N*m, no-load 50 rpm = 5.24 rad/s; at the default P 32
  -- the MX firmware's duty 0.158 * P per rad of error gives K = 0.158 * 32 * 2.3 = 11.6 N*m/rad
  -- (12.6 at 12 V; derived, not measured); b = 2.3 / 5.24 = 0.44 N*m*s/rad, so gain = K / b =
  -- 0.158 * 32 * 5.24 = 26.5/s. Torque off: the same b as back-drive damping (no MX-28 figure
  -- found; the OP3 model uses its servo's b likewise) and Webots' static friction 0.025 N*m.
  -- Present speed: about 0.114 rpm per count.
  ['MX-28'] = {
    torque = 2.3,
    speed = 5.24,                -- 50 rpm
    p_gain = 32,
    stiffness = 11.6,
    gain = 26.5,
    resolution = 4096,
    speed_unit = 0.114 * rpm,
    damping = 0.44,
    friction = 0.025,
  },
  -- Hubo2+ drives, named by reduction and torque (see hubo_drive above); the joints that use each:
  ['HUBO2-250-71'] = hubo_drive(250, 71, 1000000, 2.0),      -- WST, RHY/LHY, RAP/LAP
  ['HUBO2-506-95'] = hubo_drive(505.68, 95, 2022716, 2.0),   -- RHR/LHR
  ['HUBO2-200-95'] = hubo_drive(200, 95, 800000, 2.0),       -- RHP/LHP
  ['HUBO2-160-95'] = hubo_drive(160, 95, 640000, 2.0),       -- RKN/LKN
  ['HUBO2-316-71'] = hubo_drive(316.05, 71, 1264198, 2.0),   -- RAR/LAR
  ['HUBO2-145-35'] = hubo_drive(145.45, 35, 581818, 1.0),    -- RSP/LSP
  ['HUBO2-100-35'] = hubo_drive(100, 35, 400000, 1.0),       -- RSR/LSR
  ['HUBO2-100-25'] = hubo_drive(100, 25, 400000, 1.0),       -- RSY/LSY, REB/LEB
  ['HUBO2-100-9'] = hubo_drive(100, 9, 400000, 1.0),         -- RWY/LWY, RWP/LWP
  ['HUBO2-NECK'] = hubo_drive(100, 2.7, 12800, 0.1),         -- NK1, NK2 (128-count motor encoders)
}
