-- The right wrist's yaw set to 3.3 rad: beyond its 2.967 rad limit.
return {
  doc = 'wrist yaw beyond its limit',
  duration = 6.0,
  limbs = { rhand = { mode = 'hold' }, lhand = { mode = 'hold' } },
  joints = { RWY = 3.3 },
}
