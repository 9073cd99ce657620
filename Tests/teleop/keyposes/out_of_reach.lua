-- The right hand 0.9 m ahead of the stance frame: beyond the arm (about 0.55 m from the shoulder).
return {
  doc = 'out of reach',
  duration = 2.5,
  limbs = { rhand = { mode = 'free', pos = { 0.90, -0.25, 0.90 } }, lhand = { mode = 'hold' } },
}
