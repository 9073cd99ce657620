-- Stand up from lying on the front (Player/Motion/keyframe.lua): the OP3's motion in the DARwIn-OP's
-- joint convention, its numbers retuned in the sim (cross-entropy over the frames' angles and
-- durations on push moments 1.9..2.8 s by 0.1; arms wider apart while the chest comes up, head a
-- little up). Held out (Tests/motion/standup_stats.sh, 2 runs): front 21/28 first attempt (the
-- OP3-derived numbers: 14/28), back 19/28 (18/28). Still failing: the hips go up over the head
-- while the knees come under the body (a headstand that ends on the back).
-- Joint convention (Config/robots/darwin/robot.lua): leg pitch angles change sign, the head is
-- level at tilt 0.785, the shoulder roll's zero is 45 deg out (0.785: arm down), the elbow is
-- straight at 1.571. Angles by joint name; `mirror` gives the left side's, the right side mirrors
-- them (Player/Motion/keyframe.lua takes the signs from the axes: r = -l on this robot too).
-- Left side: shoulder pitch (negative: forward), shoulder roll, elbow; hip yaw, hip roll, hip pitch
-- (positive: flexed forward), knee (negative: bent), ankle pitch (negative: toes up), ankle roll.
return {
  frames = {
    -- arms down under the shoulders, legs straight: the chest comes up
    { duration = 0.376, hardness = 1, q = { head_pan = 0, head_tilt = 0.829 }, mirror = {
      l_sho_pitch = -1.484, l_sho_roll = 0.106, l_el = 1.571,
      l_hip_yaw = 0, l_hip_roll = 0, l_hip_pitch = 0.000, l_knee = 0.000, l_ank_pitch = 0.000, l_ank_roll = 0 } },
    -- knees and feet under the body
    { duration = 0.639, hardness = 1, q = { head_pan = 0, head_tilt = 0.829 }, mirror = {
      l_sho_pitch = -1.821, l_sho_roll = 0.488, l_el = 1.571,
      l_hip_yaw = 0, l_hip_roll = 0, l_hip_pitch = 1.583, l_knee = -2.178, l_ank_pitch = -1.320, l_ank_roll = 0 } },
    -- arms push the torso back over the feet
    { duration = 0.755, hardness = 1, q = { head_pan = 0, head_tilt = 0.829 }, mirror = {
      l_sho_pitch = -0.245, l_sho_roll = 0.536, l_el = 1.571,
      l_hip_yaw = 0, l_hip_roll = 0, l_hip_pitch = 1.654, l_knee = -2.250, l_ank_pitch = -1.241, l_ank_roll = 0 } },
    -- squat, upright
    { duration = 0.566, hardness = 1, q = { head_pan = 0, head_tilt = 0.829 }, mirror = {
      l_sho_pitch = 0.034, l_sho_roll = 0.515, l_el = 1.571,
      l_hip_yaw = 0, l_hip_roll = 0, l_hip_pitch = 1.400, l_knee = -2.250, l_ank_pitch = -1.053, l_ank_roll = 0 } },
    -- stance
    { duration = 0.800, hardness = 1, q = { head_pan = 0, head_tilt = 0.829 }, mirror = {
      l_sho_pitch = 0.000, l_sho_roll = 0.515, l_el = 1.571,
      l_hip_yaw = 0, l_hip_roll = 0, l_hip_pitch = 0.610, l_knee = -1.040, l_ank_pitch = -0.510, l_ank_roll = 0 } },
  },
}
