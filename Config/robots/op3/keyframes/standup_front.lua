-- Stand up from lying on the front (Player/Motion/keyframe.lua). q in the joint order of
-- Config/Sim/robot.lua; sym() builds a symmetric pose from the left side's angles (r = -l).
-- Left side: arm = shoulder pitch (negative: forward), shoulder roll (0: arm out sideways as in the
-- zero pose, about 1.5: hanging down), elbow; leg = hip yaw, hip roll, hip pitch (negative: flexed
-- forward), knee (positive: bent), ankle pitch (positive: toes up), ankle roll.
local function sym(head_tilt, arm, leg)
  return { 0, head_tilt, arm[1], arm[2], arm[3], leg[1], leg[2], leg[3], leg[4], leg[5], leg[6],
    -leg[1], -leg[2], -leg[3], -leg[4], -leg[5], -leg[6], -arm[1], -arm[2], -arm[3] }
end
return {
  frames = {
    -- arms down towards the ground, legs straight: the chest comes up
    { duration = 0.5, hardness = 1.0, q = sym(0, { -1.57, 1.4, 0 }, { 0, 0, 0, 0, 0, 0 }) },
    -- knees under the body
    { duration = 0.6, hardness = 1.0, q = sym(0, { -1.57, 1.4, 0 }, { 0, 0, -1.5, 2.4, 1.2, 0 }) },
    -- arms push the torso up over the feet
    { duration = 0.8, hardness = 1.0, q = sym(0, { -0.3, 1.4, 0 }, { 0, 0, -1.8, 2.4, 1.2, 0 }) },
    -- squat, upright
    { duration = 0.6, hardness = 1.0, q = sym(0, { 0, 1.3, 0 }, { 0, 0, -1.25, 2.29, 1.12, 0 }) },
    -- stance
    { duration = 0.8, hardness = 1.0, q = sym(0, { 0, 1.3, 0 }, { 0, 0, -0.61, 1.04, 0.51, 0 }) },
  },
}
