-- The pelvis 7 cm lower than the walk's stance (0.69 m) and the right hand low ahead (a board, a lever). The
-- pelvis stays a little behind the stance's middle, where the centre of mass over the feet puts it.
return {
  doc = 'pelvis lowered, right hand low ahead',
  duration = 3.0,
  limbs = {
    rhand = { mode = 'free', pos = { 0.30, -0.22, 0.65 } },
    lhand = { mode = 'hold' },
    pelvis = { mode = 'free', pos = { -0.03, 0.0, 0.62 } },
    lfoot = { mode = 'hold' },
    rfoot = { mode = 'hold' },
  },
}
