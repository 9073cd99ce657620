-- Both hands forward at shoulder height (a door's leaf, a board): the push itself is the walk's.
return {
  doc = 'both hands forward at shoulder height',
  duration = 3.0,
  limbs = {
    rhand = { mode = 'free', pos = { 0.38, -0.18, 0.95 } },
    lhand = { mode = 'free', pos = { 0.38, 0.18, 0.95 } },
    pelvis = { mode = 'follow' },
    lfoot = { mode = 'hold' },
    rfoot = { mode = 'hold' },
  },
}
