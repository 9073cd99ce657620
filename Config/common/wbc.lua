-- Whole-body control in kinematic mode (Motion.request('wbc'): Player/Motion/states/wbc.lua over
-- Modules/wbc; docs/whole-body.md): the skill the state runs. Each task: a kind (position,
-- orientation, pose, com, com_xy, posture), a frame for the frame kinds, a level (1 is the highest,
-- under the contacts), a gain (1/s: the task closes its error at gain x error), a max_rate (m/s or
-- rad/s: the fastest the task asks for), optionally a max_accel (m/s^2 or rad/s^2: how fast what it
-- asks for may change; a new target then sets it going smoothly) and a target: a list of numbers
-- (stance frame), 'stance' (com_xy: over the stance frame's origin, midway between the feet) or
-- 'entry' (posture: the pose the state started from), or none (the task rests until WBC.set_target
-- gives one).
return {
  -- the frames held on the ground (the level above every task)
  contacts = { 'l_sole', 'r_sole' },
  tasks = {
    -- balance first: the centre of mass over the middle of the feet
    -- (max_accel: a jump in the COM's speed throws the ZMP towards a sole's edge by COM height / g
    -- times the acceleration: 0.2 m/s^2 is 5 mm on the HOAP-3, 16 mm on the Hubo2+)
    com = { kind = 'com_xy', level = 1, gain = 4, max_rate = 0.05, max_accel = 0.2, target = 'stance' },
    -- the rest of the body keeps the pose it started from, in whatever freedom the tasks above leave
    posture = { kind = 'posture', level = 4, gain = 1, max_rate = 0.5, target = 'entry' },
  },
  -- WBC.set_target of a frame of the body that is not a task yet makes it a position task with these
  reach = { level = 2, gain = 3, max_rate = 0.15 },
  -- a frame's task infeasible this long (s: out of reach, at a singularity) stops chasing its target:
  -- the target becomes where the frame got to (the task `held`), so the body does not lean and twist
  -- after a point it cannot reach
  hold_after = 0.5,
  -- rad: the torso leans at most this far from upright (a step that would tilt it further stops the
  -- tilting, above every task): under the walk's fallAngleRate (0.3 rad on the Hubo2+), with margin
  max_lean = 0.25,
  -- the hardness the state drives the joints at
  hardness = 1.0,
}
