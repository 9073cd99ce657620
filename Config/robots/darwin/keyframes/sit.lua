-- Sit (Player/Motion/keyframe.lua): crouch low over the feet, then soften. The DARwIn-OP's joint
-- convention (see standup_front.lua); angles by joint name, `mirror` the left side's (r = -l).
return {
  frames = {
    { duration = 1, hardness = 0.8, q = { head_pan = 0, head_tilt = 0.785 }, mirror = {
      l_sho_pitch = 0, l_sho_roll = 0.6, l_el = 1.2,
      l_hip_yaw = 0, l_hip_roll = 0, l_hip_pitch = 1.25, l_knee = -2.25, l_ank_pitch = -1.12, l_ank_roll = 0 } },
    { duration = 0.5, hardness = 0.3, q = { head_pan = 0, head_tilt = 0.785 }, mirror = {
      l_sho_pitch = 0, l_sho_roll = 0.6, l_el = 1.2,
      l_hip_yaw = 0, l_hip_roll = 0, l_hip_pitch = 1.25, l_knee = -2.25, l_ank_pitch = -1.12, l_ank_roll = 0 } },
  },
}
