-- Sit (Player/Motion/keyframe.lua): crouch low over the feet, then soften. The DARwIn-OP's joint
-- convention (see standup_front.lua); sym() builds the 20 angles from the left side's (r = -l).
local function sym(head_tilt, arm, leg)
  return { 0, head_tilt, arm[1], arm[2], arm[3], leg[1], leg[2], leg[3], leg[4], leg[5], leg[6],
    -leg[1], -leg[2], -leg[3], -leg[4], -leg[5], -leg[6], -arm[1], -arm[2], -arm[3] }
end
return {
  frames = {
    { duration = 1.0, hardness = 0.8, q = sym(0.785, { 0, 0.6, 1.2 }, { 0, 0, 1.25, -2.25, -1.12, 0 }) },
    { duration = 0.5, hardness = 0.3, q = sym(0.785, { 0, 0.6, 1.2 }, { 0, 0, 1.25, -2.25, -1.12, 0 }) },
  },
}
