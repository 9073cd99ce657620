-- Stand up from lying on the back (Player/Motion/keyframe.lua): a backward roll onto the front; the
-- motion state machine then stands up from the front (standup_front.lua, whose header gives this
-- robot's joint convention). sym() builds a symmetric pose from the left side (r = -l).
local function sym(head_tilt, arm, leg)
  return { 0, head_tilt, arm[1], arm[2], arm[3], leg[1], leg[2], leg[3], leg[4], leg[5], leg[6],
    -leg[1], -leg[2], -leg[3], -leg[4], -leg[5], -leg[6], -arm[1], -arm[2], -arm[3] }
end
return {
  frames = {
    { duration = 0.5, hardness = 1.0, q = sym(0.785, { 0, 0.615, 1.571 }, { 0, 0, 0, 0, 0, 0 }) },
    { duration = 0.3, hardness = 1.0, q = sym(0.785, { 2.6, 0.615, 1.571 }, { 0, 0, 1.9, -0.3, 0, 0 }) },
    { duration = 0.4, hardness = 1.0, q = sym(0.785, { 1.57, 0.615, 1.571 }, { 0, 0, 1.9, -2.0, -1.0, 0 }) },
    { duration = 0.5, hardness = 1.0, q = sym(0.785, { 0, 0.615, 1.571 }, { 0, 0, 0, 0, 0, 0 }) },
    { duration = 0.5, hardness = 1.0, q = sym(0.785, { -1.2, -0.485, 1.571 }, { 0, 0, 0, 0, 0, 0 }) },
  },
}
