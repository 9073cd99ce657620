-- The OP3's sizes and speeds for the behavior (Player/BodyFSM, HeadFSM), overlaid on
-- Config/common/behavior.lua (timing, game and field numbers, and a kid-size body's defaults).
-- Units: m, s, rad. Tuned with the scoring scenario (Tests/scenarios/score_test.sh; the figures:
-- docs/results/tuning.md).
return {
  head = {
    scan_pan = 1.4,            -- rad, half-range of the scan (the head pan's reach; the camera's 43 deg
                               -- view covers 0.2-1.0 m and 0.7 m-horizon on the scan's two rows)
    turning_row_time = 0.5,    -- s (the view, ~1 rad wide, turning ~0.8 rad/s with the body: each
                               -- direction seen on both rows)
    ground_z = -0.23,          -- m: the ground below the torso origin (torso frame), for look-at
    camera_z = 0.2,            -- m, the camera above the torso origin (look-at without a kinematic model)
  },

  body = {
    -- speeds: under the walk's limits (walk.lua velLimit: 0.40, 0.15 m/s) and what it holds 30 s
    -- (0.38 m/s forward, 0.22 m/s sideways); the feet slip: 0.38 commanded walks ~0.30 m/s
    approach_speed = 0.38,     -- m/s
    max_vx = 0.38,             -- m/s
    search_turn_speed = 1.1,   -- rad/s: a ball behind is seen sooner than at 0.8
    -- a ball never seen: standing for one sweep of the head (scan_period / 2 = 2 s, the far row's
    -- +-1.4 rad: with the camera's view, +-1.9 rad round the heading) before turning, as a ball 3-4
    -- m away at 0.6-1.2 rad is seen within ~2 s in some runs and only after a whole turn in others
    search_look_time = 2.3,    -- s
    kick_x = 0.17,             -- m: ball this far ahead of the torso when kicking
    kick_y = 0.06,             -- m: ball this far to the side (towards the kicking foot)
    -- walking the ball to the goal instead of kicking (the standing kick stops the walk)
    dribble = {
      speed = 0.36,            -- m/s forward: faster scores sooner; the falls while dribbling stay rare
      start_far = 0.3,         -- m: lined up, walk into the ball from this far past the spot
      max_side = 0.2,          -- m: the ball's sway alone stays inside it (no needless re-align)
      ball_turn_gain = 0.5,    -- 1/s
      slow_side = 0.05,        -- m and rad of dead band before slowing (the estimate's jitter and
      slow_angle = 0.15,       -- the push's sway kept the walk at ~0.75 of its speed)
    },
    max_va = 0.8,              -- rad/s (faster turns with nav.far_turn_gain 2.0 score sooner but fall)
    max_vy = 0.13,             -- m/s: the align's circling (below)
    -- aligning: circling the ball (0.17 m ahead) at up to 0.8 rad/s needs ~0.14 m/s of side-step
    -- (sideways_per_turn ~ the ball's distance x the turn's gain)
    align = { gain = { 0.9, 0.9, 1.2 }, sideways_per_turn = 0.2, max_va = 0.8 },
    -- shooting with a kick out of the walk (walk.lua's walkKick.forward: the ball ~0.19 m ahead of
    -- the support ankle, in line with the kicking foot) to finish: the ball within max_range of the
    -- point aimed at (0.5 m behind the goal line), i.e. within ~1.4 m of the line. From further out
    -- the shots go wide; nearer, time goes to dribbling. The scoring figures of each setting:
    -- docs/results/tuning.md, section "OP3: behavior".
    walk_kick = {
      enabled = true,
      -- the zone the kick sends the ball 1.5 m or more from (Tests/motion/walk_kick_sweep.sh; the
      -- walk waits for a step from which the ball is near enough: walk.lua walkKick.forward.ballMax)
      x = { 0.17, 0.28 },
      y = { 0.03, 0.09 },
      x_far = 0.12,            -- m: a ball beyond x[2] by up to this is taken (the walk waits for a step)
      close_gain = 1.5,        -- 1/s: closing on a ball that rolled on (BodyFSM/kick.lua)
      follow = true,           -- the strike aimed at the ball's place at the kick step's start ...
      keep_ball = true,        -- ... seen then, not before a look at the goal
      timeout = 3.0,           -- s (a kick waits up to walkKick.expire = 2 s after it is asked)
      max_vy = 0.08,           -- m/s (the kick state stops side-stepping before it asks)
      max_range = 1.9,         -- m: the ball within 1.4 m of the goal line (the kick: 1.5-2.1 m)
      speed = 0.12,            -- m/s: the walk the kick was tuned at (walk_kick_tune.sh) ...
      max_vx = 0.14,           -- m/s: ... asked for below this (walk.lua walkKick.maxSpeed: 0.15)
    },
  },
}
