-- The centre of mass 0.25 m ahead of the stance frame: beyond the toes (the soles reach about
-- 0.13 m ahead of the ankles).
return {
  doc = 'centre of mass ahead of the toes',
  duration = 3.0,
  limbs = { rhand = { mode = 'hold' }, lhand = { mode = 'hold' }, pelvis = { mode = 'follow' } },
  com = { 0.25, 0.0 },
}
