-- The HOAP-3's walk pattern: the OpenHRP3 study's (S0 in hoap3_reference.txt): 12 steps forward on
-- the cart-table model with z_c = 0.32 m, preview control sampled at T = 5 ms with N = 300 preview
-- samples (1.5 s) and R/Q = 1e-5. z_c is the study's number: this body stands with its COM about
-- 0.30 m above the soles (bent knees, walk.lua), so the model is 7% taller than the robot it plans
-- for, as in the study.
-- S0 gives no step length, duration or lift; chosen within what the drives reach (4 rad/s, a choice
-- of actuators.lua) when the pattern is played open loop, with no feedback to make up for a joint
-- that lags: with the live walk's 0.4 s steps and 0.025 m lift the plan asks the knees for 7.5 rad/s
-- and the played knee is 4.3 deg RMS off its plan (Tests/motion/hoap3_pattern_test.sh); 0.6 s and
-- 0.015 m keep every joint within 94% of its drive's speed. 0.04 m a step, inside the live walk's
-- reach (0.048 m a step at its 0.12 m/s). A 1 s lead-in and settle (the live walk's 0.4 s): the
-- COM's first move sideways from rest in 0.4 s puts the planned ZMP 25 mm off its reference.
return {
  steps = 12,
  stepLength = 0.04,
  tStep = 0.6,
  stepHeight = 0.015,
  zc = 0.32,
  dt = 0.005,
  samples = 300,
  Qe = 1.0,
  R = 1e-5,
  lead = 1.0,
}
