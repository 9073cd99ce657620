-- The OP3's sizes and speeds for the behavior (Player/BodyFSM, HeadFSM), overlaid on
-- Config/common/behavior.lua (timing, game and field numbers, and a kid-size body's defaults).
-- Units: m, s, rad. Tuned with the scoring scenario (Tests/scenarios/score_test.sh).
return {
  head = {
    scan_pan = 1.4,            -- rad, half-range of the scan (the head pan's reach; the camera's 43 deg
                               -- view covers 0.2-1.0 m and 0.7 m-horizon on the scan's two rows)
    ground_z = -0.23,          -- m: the ground below the torso origin (torso frame), for look-at
    camera_z = 0.2,            -- m, the camera above the torso origin (look-at without a kinematic model)
  },

  body = {
    approach_speed = 0.25,     -- m/s
    kick_x = 0.17,             -- m: ball this far ahead of the torso when kicking
    kick_y = 0.06,             -- m: ball this far to the side (towards the kicking foot)
    -- walking the ball to the goal instead of kicking (the kick moves the ball < 1 m in the sim)
    dribble = {
      speed = 0.25,            -- m/s forward
    },
    max_va = 0.8,              -- rad/s
    -- shooting with a kick out of the walk (walk.lua's walkKick.forward: the ball ~0.19 m ahead of
    -- the support ankle, in line with the kicking foot). Off: the kick sends the ball 0.5-0.9 m and
    -- scoring got worse with it (Tests/scenarios/score_test.sh, 10 seeds, lockstep: without 10/10,
    -- median 63.1 s; with it, shooting within 2.5 m of the goal, 9/10 at 72.9 s and, the kick asked
    -- for only out of a slow walk, 7/10 at 71.2 s: weak kicks, and falls after them)
    walk_kick = {
      enabled = false,
      max_range = 2.5,         -- m: the kick sends the ball 0.5-0.9 m: a shot to finish, not a pass
    },
  },
}
