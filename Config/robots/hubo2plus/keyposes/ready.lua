-- Both hands in front of the belly, ready to reach or to push: the pose a task starts from.
return {
  doc = 'both hands in front of the belly',
  duration = 2.5,
  limbs = {
    rhand = { mode = 'free', pos = { 0.25, -0.22, 0.78 } },
    lhand = { mode = 'free', pos = { 0.25, 0.22, 0.78 } },
    pelvis = { mode = 'follow' },
    lfoot = { mode = 'hold' },
    rfoot = { mode = 'hold' },
  },
}
