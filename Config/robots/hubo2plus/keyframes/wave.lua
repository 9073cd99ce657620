-- Key poses for the arms and the waist while the robot stands (Lib/keypose.lua plays them through
-- Body commands; Tests/motion/sim_scenarios.lua 'keypose'): turn the upper body left and raise the
-- right arm out to the side, wave with the elbow, turn right with the left arm reaching forward,
-- then back to the walk's arm posture (Config/robots/hubo2plus/walk.lua) and the waist straight.
-- (hardness: the file format wants it; a caller's playback leaves the hardness to the motion process)
-- The Hubo's joint convention (robot.lua): shoulder pitch forward negative, right shoulder roll
-- outward negative (left positive), elbow flexion negative, waist positive to the left.
local rest = { WST = 0, LSP = 0, LSR = -0.1, LSY = 0, LEB = -0.3, RSP = 0, RSR = 0.1, RSY = 0, REB = -0.3 }
return {
  frames = {
    { duration = 2.0, hardness = 1, q = { WST = 0.5, RSP = -0.3, RSR = -1.3, REB = -1.2 } },
    { duration = 0.6, hardness = 1, q = { REB = -0.4 } },
    { duration = 0.6, hardness = 1, q = { REB = -1.3 } },
    { duration = 0.6, hardness = 1, q = { REB = -0.4 } },
    { duration = 2.0, hardness = 1,
      q = { WST = -0.5, RSP = 0, RSR = 0.1, REB = -0.3, LSP = -1.2, LSR = 0.2, LEB = -0.5 } },
    { duration = 1.0, hardness = 1, q = { LSP = -1.4, LEB = -0.1 } },
    { duration = 2.0, hardness = 1, q = rest },
  },
}
