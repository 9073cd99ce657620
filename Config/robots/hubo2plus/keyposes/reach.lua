-- The right hand forward at chest height (a handle, a valve), the left hand where it is, the feet on
-- the ground.
return {
  doc = 'right hand forward at chest height',
  duration = 2.5,
  limbs = {
    rhand = { mode = 'free', pos = { 0.35, -0.25, 0.90 } },
    lhand = { mode = 'hold' },
    pelvis = { mode = 'follow' },
    lfoot = { mode = 'hold' },
    rfoot = { mode = 'hold' },
  },
}
