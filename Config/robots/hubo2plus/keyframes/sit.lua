-- Sit (Player/Motion/keyframe.lua): a squat over the feet, torso upright, arms hanging. The Hubo's
-- joint convention (robot.lua: hip pitch forward and ankle pitch toes-up negative, knee flexion
-- positive). Joints by name (the Hubo's names have no l_/r_ prefix: no `mirror`). The servos stay
-- stiff: a 45 kg robot on soft joints folds.
local pose = {
  LHY = 0, LHR = 0, LHP = -0.7, LKN = 1.4, LAP = -0.7, LAR = 0,
  RHY = 0, RHR = 0, RHP = -0.7, RKN = 1.4, RAP = -0.7, RAR = 0,
  LSP = 0, LSR = 0, LSY = 0, LEB = -0.3, LWY = 0, LWP = 0,
  RSP = 0, RSR = 0, RSY = 0, REB = -0.3, RWY = 0, RWP = 0,
}
return {
  frames = {
    { duration = 3, hardness = 1, q = pose },
  },
}
