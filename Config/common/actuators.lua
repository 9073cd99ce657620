-- Actuator models: what a joint's servo can do. A robot names one per joint in robot.lua
-- (`actuator = { l_knee = 'MX-28', ... }`); a robot with a servo not listed here adds its model in
-- Config/robots/<robot>/actuators.lua (same fields). Used by:
--   Run/gen_urdf.py   writes torque, speed, damping and friction into the robot's URDF (<limit>
--                     effort/velocity, <dynamics> damping/friction), so the URDF carries them;
--   the sim (Platforms/Sim/world.cpp)   drives each joint as an ODE hinge velocity motor:
--                     target speed = gain * (command - position), clamped to the URDF velocity,
--                     at most hardness * URDF effort of torque; torque off: URDF damping/friction;
--                     positions quantised to `resolution`, speeds to `speed_unit`.
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
}
