-- The HOAP-3's drives (Config/robots/hoap3/robot.lua names one per joint; the fields are those of
-- Config/common/actuators.lua). From ../shared/robots/hoap3_reference.txt (ref): 21 joint motors in two
-- torque tiers and 7 small servos; the ref has no motor data (gear ratios, speeds, constants), so what
-- it lacks is chosen here, conservatively, and said so:
--   torque  the second figure of S6's torque pairs (1.5 / 3 and 2 / 4.5 N*m; the wrists 0.28 / 0.36),
--           which S8's OpenRAVE model gives as its maximum torques (3 and 4.5 N*m): the peak torque,
--           the sim's limit. The waist: S6's 4.5 N*m, not S8's 1.5, which cannot hold the trunk (its
--           3.26 kg COM 0.085 m behind the waist-pitch axis needs 2.7 N*m, the arms and head ~3.4
--           in all). The head's three servos: torque unknown; the wrists' small servos (S7 counts head,
--           wrist and gripper servos as one kind), 0.36 N*m against ~0.02 N*m of head weight about
--           the neck axes;
--   speed   unknown (S8's "maxvel 35" has no unit): 4.0 rad/s, slower than the HOAP-2 model's 5 rad/s
--           (S10) and the small Dynamixels (MX-28 5.24, XM430 4.82 rad/s), so the sim's joints are not
--           faster than any drive of this class;
--   gain    30/s, the loop gain of the other models (no servo gains in the ref): stiffness
--           gain * torque / speed;
--   damping torque off: b = torque / speed as the other models; friction 0.05 N*m back-drive (chosen,
--           of the order of the small geared servos' 0.025-0.03 N*m, a little more for a larger gear);
--   resolution  209 encoder counts per joint degree (S4, S6): 75240 per turn; speed_unit one count
--           per 5 ms control cycle (robot.lua's period; no speed register in the ref).
local COUNTS = 209 * 360
local PERIOD = 0.005
local SPEED = 4.0

local function drive(torque, friction)
  return {
    torque = torque,
    speed = SPEED,
    p_gain = 0,                  -- no position-gain register in the ref
    stiffness = 30 * torque / SPEED,
    gain = 30,
    resolution = COUNTS,
    speed_unit = 2 * math.pi / COUNTS / PERIOD,
    damping = torque / SPEED,
    friction = friction,
  }
end

return {
  ['HOAP3-3'] = drive(3.0, 0.05),      -- 3 N*m: hip yaw, hip pitch, ankle roll, shoulder pitch/roll, arm yaw, elbow
  ['HOAP3-45'] = drive(4.5, 0.05),     -- 4.5 N*m: hip roll, knee, ankle pitch, waist pitch
  ['HOAP3-SERVO'] = drive(0.36, 0.01), -- head pan/tilt/roll, wrist yaw (small servos)
}
