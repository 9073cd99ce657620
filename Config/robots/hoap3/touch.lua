-- The HOAP-3 touching a wall in front of it with both hands (the study's wall touch): from the walk's
-- hanging arms (shoulder pitch +pi/2 is down: robot.lua's zero points the arms forward), both arms
-- swing forward and up, straight at the elbow, to 0.3 rad above horizontal, each stopping on its
-- wrist force sensor.
return {
  arms = {
    { sensor = 'lhand', to = { l_sho_pitch = -0.3, l_sho_roll = 0.1, l_arm_yaw = 0, l_el = 0, l_wrist_yaw = 0 } },
    { sensor = 'rhand', to = { r_sho_pitch = -0.3, r_sho_roll = -0.1, r_arm_yaw = 0, r_el = 0, r_wrist_yaw = 0 } },
  },
}
