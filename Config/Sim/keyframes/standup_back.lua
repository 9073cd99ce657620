-- Stand up from lying on the back (Player/Motion/keyframe.lua). Same conventions as
-- standup_front.lua: sym() builds a symmetric pose from the left side's angles (r = -l).
local function sym(head_tilt, arm, leg)
  return { 0, head_tilt, arm[1], arm[2], arm[3], leg[1], leg[2], leg[3], leg[4], leg[5], leg[6],
    -leg[1], -leg[2], -leg[3], -leg[4], -leg[5], -leg[6], -arm[1], -arm[2], -arm[3] }
end
return {
  frames = {
    { duration = 0.5, hardness = 0.8, q = sym(0, { 0.8, -0.2, 0 }, { 0, 0, 0, 0, 0, 0 }) },
    { duration = 0.6, hardness = 1.0, q = sym(0, { 1.6, -0.2, 0 }, { 0, 0, -1.6, 2.2, 1.0, 0 }) },
    { duration = 0.8, hardness = 1.0, q = sym(0, { 2.2, -0.2, 0 }, { 0, 0, -1.6, 2.3, 1.1, 0 }) },
    { duration = 0.6, hardness = 1.0, q = sym(0, { 0, -0.25, 0 }, { 0, 0, -1.25, 2.29, 1.12, 0 }) },
    { duration = 0.8, hardness = 1.0, q = sym(0, { 0, -0.25, 0 }, { 0, 0, -0.61, 1.04, 0.51, 0 }) },
  },
}
