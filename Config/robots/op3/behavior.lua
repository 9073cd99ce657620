-- The OP3's sizes and speeds for the behavior (Player/BodyFSM, HeadFSM), overlaid on
-- Config/common/behavior.lua (timing, game and field numbers, and a kid-size body's defaults).
-- Units: m, s, rad. Tuned with the scoring scenario (Tests/scenarios/score_test.sh).
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
    approach_speed = 0.38,     -- m/s (was 0.32)
    max_vx = 0.38,             -- m/s (was 0.34)
    search_turn_speed = 1.1,   -- rad/s (was 0.8: a ball behind was first seen 0.8 s sooner, score_test)
    -- a ball never seen: standing for one sweep of the head (scan_period / 2 = 2 s, the far row's
    -- +-1.4 rad: with the camera's view, +-1.9 rad round the heading) before turning: a ball 3-4 m
    -- away at 0.6-1.2 rad was seen at ~2 s in some runs and after a whole turn (~8 s) in others
    -- (score_test's seeds 1, 5, 7)
    search_look_time = 2.3,    -- s
    kick_x = 0.17,             -- m: ball this far ahead of the torso when kicking
    kick_y = 0.06,             -- m: ball this far to the side (towards the kicking foot)
    -- walking the ball to the goal instead of kicking (the standing kick stops the walk)
    -- (scoring, Tests/scenarios/score_test.sh, 10 seeds, lockstep, the same loaded machine, two
    -- runs each: with the speeds, dribbling and search as they were 10/10 and 10/10, medians 54.9
    -- and 57.4 s, 0 and 1 falls, walking 0.23 m/s while dribbling; these: 10/10 and 9/10, 45.6
    -- and 46.1 s, 1 and 3 falls (2 in the miss: the ball on the goal line by a post, the pose
    -- lost there), 0.27 m/s; Tools/plot/trace_stats.py for the time per state)
    dribble = {
      speed = 0.36,            -- m/s forward (was 0.3; at 0.32 one run of 10 once fell dribbling;
                               -- at 0.36, in 13 runs of 10: 2 falls while dribbling)
      start_far = 0.3,         -- m: lined up, walk into the ball from this far past the spot
      max_side = 0.2,          -- m (was 0.16: the ball's sway alone made the robot align again)
      ball_turn_gain = 0.5,    -- 1/s
      slow_side = 0.05,        -- m and rad of dead band before slowing (the estimate's jitter and
      slow_angle = 0.15,       -- the push's sway kept the walk at ~0.75 of its speed)
    },
    max_va = 0.8,              -- rad/s (1.2 with nav.far_turn_gain 2.0: 10/10 39.6 s, then 8/10 with
                               -- 6 falls, score_test)
    max_vy = 0.13,             -- m/s (was the common 0.1: the align's circling, below)
    -- aligning: circling the ball (0.17 m ahead) at up to 0.8 rad/s needs ~0.14 m/s of side-step
    -- (sideways_per_turn ~ the ball's distance x the turn's gain); the common gains took 6.4 s a
    -- run in score_test, these 4.4-4.9 s (Tools/plot/trace_stats.py)
    align = { gain = { 0.9, 0.9, 1.2 }, sideways_per_turn = 0.2, max_va = 0.8 },
    -- shooting with a kick out of the walk (walk.lua's walkKick.forward: the ball ~0.19 m ahead of
    -- the support ankle, in line with the kicking foot) to finish: the ball within max_range of the
    -- point aimed at (0.5 m behind the goal line), i.e. within ~0.9 m of the line. Scoring
    -- (Tests/scenarios/score_test.sh, 10 seeds, lockstep, these speeds, a loaded machine: runs of
    -- one setting differ by ~5 s in the median): without it 10/10, median 56.3 s; with the
    -- 1.0-1.26 m kick 10/10, 54.8 s, no fall; with the 1.05-1.41 m kick 9/10, 57.8 s (the miss: a
    -- shot on a wrong pose; 3 falls in one run, while approaching). From further out the kick costs
    -- more (slowing for it, approach and align after it) than it gains over dribbling at 0.3 m/s.
    -- With the 1.5-2.1 m kick (session 13, one run each; the first four beside a league): max_range
    -- 1.4 9/10, median 48.1 s; 1.9 9/10 44.1 s, 10/10 50.1 s, then alone in make test 9/10 51.3 s
    -- and 10/10 46.0 s; 2.2 7/10, 51.6 s (shots from 1.7 m of the line went wide and out). Time
    -- still goes to dribbling (~24 s a run at 0.28 m/s). Session 14 (one run each, beside a push
    -- tuning run): as above 8/10, 45.9 s; closing on the ball, x_far, max_vy 0.08 and the search's
    -- look 10/10, 44.5 s; and the search turning at 1.1 rad/s 10/10, 42.5 s; max_range 2.3 with
    -- both 9/10, 46.1 s (shots from ~1.5 m of the line needed a second kick); the look only for a
    -- ball never seen (as configured: match_test) 10/10 43.2 s, in make test 44.5 and 46.3 s, in
    -- CI 39.7 s. Session 15: the kick aimed at the ball as seen at its step (follow, keep_ball; the
    -- kicks had gone 1.0-1.6 m, half the runs needing a second one) and the mouth test: 10/10 43.2
    -- and 44.4 s (before: 9/10 47.9, 10/10 44.3 s); max_range 2.1 with it 10/10 47.2 and 43.7 s.
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
