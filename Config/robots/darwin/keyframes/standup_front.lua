-- Stand up from lying on the front (Player/Motion/keyframe.lua): the OP3's motion in the DARwIn-OP's
-- joint convention, its numbers retuned in the sim (cross-entropy over the frames' angles and
-- durations; arms wider apart while the chest comes up, head a little up), after a first frame that
-- puts the arms out sideways along the ground: lying on its arms (as the roll from the back leaves
-- it) the robot could not swing them down to lift the chest and ended in a headstand. Held out
-- (Tools/tune/standup_stats.sh, clean trials): front 14/14 first attempt, back 14/14.
-- Joint convention (Config/robots/darwin/robot.lua): leg pitch angles change sign, the head is
-- level at tilt 0.785, the shoulder roll's zero is 45 deg out (0.785: arm down), the elbow is
-- straight at 1.571. Angles by joint name; `mirror` gives the left side's, the right side mirrors
-- them (Player/Motion/keyframe.lua takes the signs from the axes: r = -l on this robot too).
-- Left side: shoulder pitch (negative: forward), shoulder roll, elbow; hip yaw, hip roll, hip pitch
-- (positive: flexed forward), knee (negative: bent), ankle pitch (negative: toes up), ankle roll.
return {
  frames = {
    -- arms out sideways along the ground (after a roll from the back they lie along the body, under
    -- it: from there they could not swing down through the ground to lift the chest)
    { duration = 0.3, hardness = 1, q = { head_pan = 0, head_tilt = 0.829 }, mirror = {
      l_sho_pitch = -1.2, l_sho_roll = -0.8, l_el = 1.571,
      l_hip_yaw = 0, l_hip_roll = 0, l_hip_pitch = 0, l_knee = 0, l_ank_pitch = 0, l_ank_roll = 0 } },
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
