-- Sit (Player/Motion/keyframe.lua): crouch low over the feet, then soften.
-- q in the joint order of Config/Sim/robot.lua; the right side's axes mirror the left's, so a
-- symmetric pose has r = -l (sym() below builds the 20 angles from the left side's).
local function sym(head_tilt, arm, leg)
  return { 0, head_tilt, arm[1], arm[2], arm[3], leg[1], leg[2], leg[3], leg[4], leg[5], leg[6],
    -leg[1], -leg[2], -leg[3], -leg[4], -leg[5], -leg[6], -arm[1], -arm[2], -arm[3] }
end
return {
  frames = {
    { duration = 1.0, hardness = 0.8, q = sym(0, { 0, -0.25, 0 }, { 0, 0, -1.25, 2.29, 1.12, 0 }) },
    { duration = 0.5, hardness = 0.3, q = sym(0, { 0, -0.25, 0 }, { 0, 0, -1.25, 2.29, 1.12, 0 }) },
  },
}
