-- Stand up from lying on the front (Player/Motion/keyframe.lua): the OP3's motion in the DARwIn-OP's
-- joint convention (Config/robots/darwin/robot.lua): leg pitch angles change sign, the head is level
-- at tilt 0.785, the shoulder roll's zero is 45 deg out (0.785: arm down), the elbow is straight at
-- 1.571. Angles by joint name; `mirror` gives the left side's, the right side mirrors them
-- (Player/Motion/keyframe.lua takes the signs from the axes: r = -l on this robot too).
-- Left side: shoulder pitch (negative: forward), shoulder roll, elbow; hip yaw, hip roll, hip pitch
-- (positive: flexed forward), knee (negative: bent), ankle pitch (negative: toes up), ankle roll.
-- Angles beyond a joint's limit are clamped by Body.
return {
  frames = {
    -- arms down towards the ground, legs straight: the chest comes up
    { duration = 0.5, hardness = 1, q = { head_pan = 0, head_tilt = 0.785 }, mirror = {
      l_sho_pitch = -1.57, l_sho_roll = 0.615, l_el = 1.571,
      l_hip_yaw = 0, l_hip_roll = 0, l_hip_pitch = 0, l_knee = 0, l_ank_pitch = 0, l_ank_roll = 0 } },
    -- knees under the body
    { duration = 0.6, hardness = 1, q = { head_pan = 0, head_tilt = 0.785 }, mirror = {
      l_sho_pitch = -1.57, l_sho_roll = 0.615, l_el = 1.571,
      l_hip_yaw = 0, l_hip_roll = 0, l_hip_pitch = 1.5, l_knee = -2.4, l_ank_pitch = -1.2, l_ank_roll = 0 } },
    -- arms push the torso up over the feet
    { duration = 0.8, hardness = 1, q = { head_pan = 0, head_tilt = 0.785 }, mirror = {
      l_sho_pitch = -0.3, l_sho_roll = 0.615, l_el = 1.571,
      l_hip_yaw = 0, l_hip_roll = 0, l_hip_pitch = 1.8, l_knee = -2.4, l_ank_pitch = -1.2, l_ank_roll = 0 } },
    -- squat, upright
    { duration = 0.6, hardness = 1, q = { head_pan = 0, head_tilt = 0.785 }, mirror = {
      l_sho_pitch = 0, l_sho_roll = 0.515, l_el = 1.571,
      l_hip_yaw = 0, l_hip_roll = 0, l_hip_pitch = 1.25, l_knee = -2.29, l_ank_pitch = -1.12, l_ank_roll = 0 } },
    -- stance
    { duration = 0.8, hardness = 1, q = { head_pan = 0, head_tilt = 0.785 }, mirror = {
      l_sho_pitch = 0, l_sho_roll = 0.515, l_el = 1.571,
      l_hip_yaw = 0, l_hip_roll = 0, l_hip_pitch = 0.61, l_knee = -1.04, l_ank_pitch = -0.51, l_ank_roll = 0 } },
  },
}
