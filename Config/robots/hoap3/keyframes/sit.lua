-- Sit (Player/Motion/keyframe.lua): a squat over the feet, the torso 0.17 m above the soles and
-- leaning 0.2 rad forward (the trunk's COM is behind the hips), arms hanging; then a little softer.
-- The HOAP-3's joint convention (robot.lua: hip pitch forward negative, knee flexion positive, the
-- arms forward at zero: shoulder pitch +pi/2 hangs them); angles by joint name, `mirror` the left
-- side's. The knees keep their torque: in this squat each carries about 3 of its 4.5 N*m.
local function pose(hardness, duration)
  return { duration = duration, hardness = hardness,
    q = { waist_pitch = 0, head_pan = 0, head_tilt = 0, head_roll = 0 },
    mirror = {
      l_sho_pitch = 1.5708, l_sho_roll = 0.1, l_arm_yaw = 0, l_el = -0.3, l_wrist_yaw = 0,
      l_hip_yaw = 0, l_hip_roll = 0, l_hip_pitch = -1.1, l_knee = 1.8, l_ank_pitch = -0.9, l_ank_roll = 0,
    } }
end
return {
  frames = { pose(1.0, 2.0), pose(0.8, 0.5) },
}
