-- Walk patterns generated ahead and played back (Tools/pattern/gen_pattern.lua writes a joint
-- trajectory file, Lib/trajectory.lua; the motion state `pattern` plays it: docs/motion.md).
-- Units: m, s. `false`: the live walk's value (Config/common/walk.lua and the body's walk.lua).
return {
  -- the generator: the walk engine with ZMP preview control (Player/Motion/walk_preview.lua), run
  -- offline over a footstep plan of `steps` steps forward, each swing foot landing `stepLength`
  -- ahead of the support foot (the first from feet together, the last closing the feet)
  steps = 12,
  stepLength = 0.04,         -- m
  tStep = false,             -- s, one step (false: walk.tStep)
  stepHeight = false,        -- m, the swing foot's lift (false: walk.stepHeight)
  zc = false,                -- m, the cart-table model's COM height (false: walk.tZmp^2 g)
  dt = false,                -- s, the preview controller's sample time T (false: robot.period)
  samples = false,           -- N, preview samples (false: walk.preview.window / dt)
  Qe = false,                -- weight of the ZMP error (false: walk.preview.Qe)
  R = false,                 -- weight of the COM jerk (false: walk.preview.R)
  lead = false,              -- s in double support before the first step and after the last (false:
                             -- walk.preview.lead)
  hold = 1.0,                -- s of stance written after the COM has come to rest
  -- the player: from the pose at the request to the file's first row in `blend` s, then the rows
  -- at the file's times (linear between them) on the motion tick; the walk's hardness
  blend = 1.0,               -- s
}
