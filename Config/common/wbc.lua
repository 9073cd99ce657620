-- Whole-body control in kinematic mode (Motion.request('wbc'): Player/Motion/states/wbc.lua over
-- Modules/wbc; docs/whole-body.md): the skill the state runs. Each task: a kind (position,
-- orientation, pose, com, com_xy, posture), a frame for the frame kinds, a level (1 is the highest,
-- under the contacts), a gain (1/s: the task closes its error at gain x error), a max_rate (m/s or
-- rad/s: the fastest the task asks for) and a target: a list of numbers (stance frame), 'stance'
-- (com_xy: over the stance frame's origin, midway between the feet) or 'entry' (posture: the pose the
-- state started from), or none (the task rests until WBC.set_target gives one).
return {
  -- the frames held on the ground (the level above every task)
  contacts = { 'l_sole', 'r_sole' },
  tasks = {
    -- balance first: the centre of mass over the middle of the feet
    com = { kind = 'com_xy', level = 1, gain = 4, max_rate = 0.05, target = 'stance' },
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
  -- Torque mode (Player/Motion/wbc_torque.lua, docs/whole-body.md): with `enabled`, the joints of
  -- `group` are torque driven by operational-space control of `frame` (its target: WBC.set_target of
  -- that frame, stance frame; nil: no task), the rest of the body stays in position mode. Off by
  -- default: on the bodies without a torque path the DCM refuses torque mode. Live through param()
  -- (param('wbc.torque.enabled', true), param('wbc.torque.kp', 0)).
  torque = {
    enabled = false,
    group = 'rarm',
    frame = 'r_palm',
    -- the frame's task: 1/s^2 and 1/s, its error's natural frequency 20 rad/s (3.2 Hz) critically
    -- damped: fast beside the 0.5 Hz motions it is for, slow beside the 200 Hz control rate and
    -- its one-period delay
    kp = 400,
    kd = 40,
    -- the posture in the task's null space (the arm's angles at the switch to torque mode): the
    -- redundant directions held, softer than the task
    posture_kp = 100,
    posture_kd = 20,
    -- 1/s: joint damping (weighted by the arm's mass matrix) in the task's null space, with no task
    -- everywhere; it stays when the posture's gains are zero. Against the joints' slow creep under a
    -- gravity compensation that is exact in the model (docs/whole-body.md, Torque mode); a fifth of
    -- the posture's damping, so it leaves the posture and the task their own.
    damping = 4,
    -- s: the joint damping's rate is the angle's change over this window, not the encoder's
    -- one-period difference (one count per 5 ms is 3 mrad/s on the Hubo2+'s arms)
    rate_window = 0.05,
    -- the gears' friction (the actuators' `friction`, Config/common/actuators.lua: 1 N m on the
    -- Hubo2+'s arms), this fraction of it compensated in the direction the joint moves (the task's
    -- joint rates while its target moves, else the measured rate; with no target none), smoothly
    -- within friction_band rad/s of zero. Under 1: a friction a little less than the data says is not over-compensated
    -- into a push; without it the arm lags a 0.5 Hz circle by 20 mm RMS in a model with the data's
    -- friction.
    friction = 0.9,
    friction_band = 0.02,
  },
}
