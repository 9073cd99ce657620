-- The pelvis 6 cm lower and the right hand low ahead (a board on the ground's edge, a lever).
return {
  doc = 'pelvis lowered, right hand low ahead',
  duration = 3.0,
  limbs = {
    rhand = { mode = 'free', pos = { 0.30, -0.22, 0.65 } },
    lhand = { mode = 'hold' },
    pelvis = { mode = 'free', pos = { 0.0, 0.0, 0.60 } },
    lfoot = { mode = 'hold' },
    rfoot = { mode = 'hold' },
  },
}
