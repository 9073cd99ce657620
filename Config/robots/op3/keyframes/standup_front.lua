-- Stand up from lying on the front (Player/Motion/keyframe.lua). Angles by joint name (robot.lua
-- beside this folder); `mirror` gives the left side's, the right side mirrors them (Player/Motion/
-- keyframe.lua derives the signs from the axes: here r = -l). Left side: shoulder pitch (negative:
-- forward), shoulder roll (0: arm out sideways as in the zero pose, about 1.5: hanging down), elbow;
-- hip yaw, hip roll, hip pitch (negative: flexed forward), knee (positive: bent), ankle pitch
-- (positive: toes up), ankle roll.
local head = { head_pan = 0, head_tilt = 0 }
return {
  frames = {
    -- arms down towards the ground, legs straight: the chest comes up
    { duration = 0.5, hardness = 1.0, q = head, mirror = {
      l_sho_pitch = -1.57, l_sho_roll = 1.4, l_el = 0,
      l_hip_yaw = 0, l_hip_roll = 0, l_hip_pitch = 0, l_knee = 0, l_ank_pitch = 0, l_ank_roll = 0 } },
    -- knees under the body
    { duration = 0.6, hardness = 1.0, q = head, mirror = {
      l_sho_pitch = -1.57, l_sho_roll = 1.4, l_el = 0,
      l_hip_yaw = 0, l_hip_roll = 0, l_hip_pitch = -1.5, l_knee = 2.4, l_ank_pitch = 1.2, l_ank_roll = 0 } },
    -- arms push the torso up over the feet
    { duration = 0.8, hardness = 1.0, q = head, mirror = {
      l_sho_pitch = -0.3, l_sho_roll = 1.4, l_el = 0,
      l_hip_yaw = 0, l_hip_roll = 0, l_hip_pitch = -1.8, l_knee = 2.4, l_ank_pitch = 1.2, l_ank_roll = 0 } },
    -- squat, upright
    { duration = 0.6, hardness = 1.0, q = head, mirror = {
      l_sho_pitch = 0, l_sho_roll = 1.3, l_el = 0,
      l_hip_yaw = 0, l_hip_roll = 0, l_hip_pitch = -1.25, l_knee = 2.29, l_ank_pitch = 1.12, l_ank_roll = 0 } },
    -- stance
    { duration = 0.8, hardness = 1.0, q = head, mirror = {
      l_sho_pitch = 0, l_sho_roll = 1.3, l_el = 0,
      l_hip_yaw = 0, l_hip_roll = 0, l_hip_pitch = -0.61, l_knee = 1.04, l_ank_pitch = 0.51, l_ank_roll = 0 } },
  },
}
