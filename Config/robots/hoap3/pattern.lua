-- The HOAP-3's walk pattern: the OpenHRP3 study's (S0 in hoap3_reference.txt): 12 steps forward on
-- the cart-table model with z_c = 0.32 m, preview control sampled at T = 5 ms with N = 300 preview
-- samples (1.5 s) and R/Q = 1e-5. S0 gives no step length or duration: the live walk's 0.4 s
-- steps (walk.lua), and 0.04 m, inside what that walk reaches (0.048 m a step at its 0.12 m/s).
-- z_c is the study's number: this body stands with its COM about 0.30 m above the soles (bent
-- knees, walk.lua), so the model is 6% taller than the robot it plans for, as in the study.
return {
  steps = 12,
  stepLength = 0.04,
  zc = 0.32,
  dt = 0.005,
  samples = 300,
  Qe = 1.0,
  R = 1e-5,
}
