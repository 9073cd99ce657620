-- Sit (Player/Motion/keyframe.lua): crouch low over the feet, then soften. Angles by joint name
-- (robot.lua beside this folder); `mirror` gives the left side's, the right side mirrors them.
local crouch = {
  l_sho_pitch = 0, l_sho_roll = -0.25, l_el = 0,
  l_hip_yaw = 0, l_hip_roll = 0, l_hip_pitch = -1.25, l_knee = 2.29, l_ank_pitch = 1.12, l_ank_roll = 0,
}
local head = { head_pan = 0, head_tilt = 0 }
return {
  frames = {
    { duration = 1.0, hardness = 0.8, q = head, mirror = crouch },
    { duration = 0.5, hardness = 0.3, q = head, mirror = crouch },
  },
}
