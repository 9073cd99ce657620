-- The DARwIn-OP's sizes and speeds for the behavior (Player/BodyFSM, HeadFSM), overlaid on
-- Config/common/behavior.lua (timing, game and field numbers, and a kid-size body's defaults).
-- Units: m, s, rad. The OP3's numbers (Config/robots/op3/behavior.lua) scaled to the smaller body
-- where they depend on its size: the torso origin 0.225 m up when walking (OP3 0.25), the camera
-- 0.18 m above it, the toe 0.052 m ahead of the ankle and the sole's centre 0.048 m out from the
-- middle (OP3 0.064, 0.058).
return {
  head = {
    scan_pan = 1.4,            -- rad, half-range of the scan (the head pan's reach; the camera's 46 deg
                               -- view covers about 0.2-1.0 m and 0.7 m-horizon on the scan's two rows)
    ground_z = -0.21,          -- m: the ground below the torso origin (torso frame), for look-at
    camera_z = 0.18,           -- m, the camera above the torso origin (look-at without a kinematic model)
    -- looks at the goal more often than the OP3 (Config/common/behavior.lua): it walks slower, so
    -- more odometry drift piles up between post sightings per metre
    look_goal_every = 4.0,     -- s
    look_goal_every_near = 2.0, -- s
  },

  body = {
    approach_speed = 0.28,     -- m/s (its walk makes 0.279 m/s of a 0.30 command)
    kick_x = 0.15,             -- m: ball this far ahead of the torso when kicking
    kick_y = 0.05,             -- m: ball this far to the side (towards the kicking foot)
    -- walking the ball to the goal instead of kicking (the kick moves the ball < 1 m in the sim)
    dribble = {
      speed = 0.28,            -- m/s forward
    },
    max_va = 0.8,              -- rad/s
  },
}
