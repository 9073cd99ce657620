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
    kp = 900,
    kd = 60,
    -- the posture in the task's null space (the arm's angles at the switch to torque mode): the
    -- redundant directions held, softer than the task
    posture_kp = 100,
    posture_kd = 20,
    -- 1/s: joint damping (weighted by the arm's mass matrix) in the task's null space, with no task
    -- everywhere; it stays when the posture's gains are zero, so the redundant directions do not
    -- swing freely. A strong one costs tracking (a 0.5 Hz circle 6 mm RMS at 4-10/s, 8 mm at 100/s).
    damping = 10,
    -- s: the joint damping's rate is the angle's change over this window, not the encoder's
    -- one-period difference (one count per 5 ms is 3 mrad/s on the Hubo2+'s arms)
    rate_window = 0.05,
    -- the gears' friction (the actuators' `friction`, Config/common/actuators.lua: 1 N m on the
    -- Hubo2+'s arms) compensated in the direction the joint moves, smoothly within friction_band
    -- rad/s of zero: `friction` of it along the task's joint rates while its target moves (without
    -- it the arm lags a 0.5 Hz circle by 20 mm RMS in a model with the data's friction), and
    -- `friction_measured` along the measured rates while the target stands (the encoders' rate is
    -- quantised and late, and the compensation stops with the motion: with the gears' friction held
    -- in the sim, a 20 N push on the Hubo2+'s palm moves it 0.86 of F/K at 0.9 but the friction then
    -- holds it 10-13 mm from where it was after the release; at 0.5 it returns within 5 mm but moves
    -- a fraction of F/K: docs/whole-body.md, Torque mode). No target: none, the friction helps hold
    -- the arm.
    friction = 0.9,
    friction_measured = 0.5,
    friction_band = 0.02,
  },
}
