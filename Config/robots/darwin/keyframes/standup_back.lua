-- Stand up from lying on the back (Player/Motion/keyframe.lua): a backward roll onto the front; the
-- motion state machine then stands up from the front (standup_front.lua, whose header gives this
-- robot's joint convention). The arms go out sideways while the body rolls over, so that it does
-- not land on them. Angles by joint name, `mirror` the left side's (r = -l).
return {
  frames = {
    { duration = 0.5, hardness = 1, q = { head_pan = 0, head_tilt = 0.785 }, mirror = {
      l_sho_pitch = 0, l_sho_roll = 0.615, l_el = 1.571,
      l_hip_yaw = 0, l_hip_roll = 0, l_hip_pitch = 0, l_knee = 0, l_ank_pitch = 0, l_ank_roll = 0 } },
    { duration = 0.3, hardness = 1, q = { head_pan = 0, head_tilt = 0.785 }, mirror = {
      l_sho_pitch = 2.6, l_sho_roll = 0.615, l_el = 1.571,
      l_hip_yaw = 0, l_hip_roll = 0, l_hip_pitch = 1.9, l_knee = -0.3, l_ank_pitch = 0, l_ank_roll = 0 } },
    { duration = 0.4, hardness = 1, q = { head_pan = 0, head_tilt = 0.785 }, mirror = {
      l_sho_pitch = 1.57, l_sho_roll = 0.615, l_el = 1.571,
      l_hip_yaw = 0, l_hip_roll = 0, l_hip_pitch = 1.9, l_knee = -2, l_ank_pitch = -1, l_ank_roll = 0 } },
    { duration = 0.5, hardness = 1, q = { head_pan = 0, head_tilt = 0.785 }, mirror = {
      l_sho_pitch = 0, l_sho_roll = -0.8, l_el = 1.571,
      l_hip_yaw = 0, l_hip_roll = 0, l_hip_pitch = 0, l_knee = 0, l_ank_pitch = 0, l_ank_roll = 0 } },
    { duration = 0.5, hardness = 1, q = { head_pan = 0, head_tilt = 0.785 }, mirror = {
      l_sho_pitch = -1.2, l_sho_roll = -0.485, l_el = 1.571,
      l_hip_yaw = 0, l_hip_roll = 0, l_hip_pitch = 0, l_knee = 0, l_ank_pitch = 0, l_ank_roll = 0 } },
  },
}
