-- Stand up from lying on the front (Player/Motion/keyframe.lua): the OP3's motion in the DARwIn-OP's
-- joint convention (Config/robots/darwin/robot.lua): leg pitch angles change sign, the head is level
-- at tilt 0.785, the shoulder roll's zero is 45 deg out (0.785: arm down), the elbow is straight at
-- 1.571. sym() builds a symmetric pose from the left side's angles (r = -l on this robot too).
-- Left side: arm = shoulder pitch (negative: forward), shoulder roll, elbow; leg = hip yaw, hip
-- roll, hip pitch (positive: flexed forward), knee (negative: bent), ankle pitch (negative: toes up),
-- ankle roll. Angles beyond a joint's limit are clamped by Body.
local function sym(head_tilt, arm, leg)
  return { 0, head_tilt, arm[1], arm[2], arm[3], leg[1], leg[2], leg[3], leg[4], leg[5], leg[6],
    -leg[1], -leg[2], -leg[3], -leg[4], -leg[5], -leg[6], -arm[1], -arm[2], -arm[3] }
end
return {
  frames = {
    -- arms down towards the ground, legs straight: the chest comes up
    { duration = 0.5, hardness = 1.0, q = sym(0.785, { -1.57, 0.615, 1.571 }, { 0, 0, 0, 0, 0, 0 }) },
    -- knees under the body
    { duration = 0.6, hardness = 1.0, q = sym(0.785, { -1.57, 0.615, 1.571 }, { 0, 0, 1.5, -2.4, -1.2, 0 }) },
    -- arms push the torso up over the feet
    { duration = 0.8, hardness = 1.0, q = sym(0.785, { -0.3, 0.615, 1.571 }, { 0, 0, 1.8, -2.4, -1.2, 0 }) },
    -- squat, upright
    { duration = 0.6, hardness = 1.0, q = sym(0.785, { 0, 0.515, 1.571 }, { 0, 0, 1.25, -2.29, -1.12, 0 }) },
    -- stance
    { duration = 0.8, hardness = 1.0, q = sym(0.785, { 0, 0.515, 1.571 }, { 0, 0, 0.61, -1.04, -0.51, 0 }) },
  },
}
