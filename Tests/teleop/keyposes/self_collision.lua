-- The right hand into the chest: on the way the wrist sweeps past the thigh, and the hand ends inside the
-- torso's box.
return {
  doc = 'hand into the chest',
  duration = 3.0,
  limbs = { rhand = { mode = 'free', pos = { 0.08, -0.02, 0.85 } }, lhand = { mode = 'hold' } },
}
