-- The HOAP-3's sizes and speeds for the behavior (Player/BodyFSM, HeadFSM), overlaid on
-- Config/common/behavior.lua (timing, game and field numbers, and a kid-size body's defaults).
-- Units: m, s, rad. The body (hoap3_reference.txt, walk.lua): the torso origin 0.24 m up when
-- walking, leaning forward 0.15 rad; the right eye 0.28 m above the torso origin and 0.065 m ahead
-- of it at the zero pose; the neck tilts 45 deg down at most (the OP3's 69); the toe 0.068 m ahead
-- of the ankle. Its walk is slow (walk.lua's limits 0.15 m/s forward, 0.05 sideways, 0.5 rad/s,
-- under what it holds 30 s: 0.177, 0.070, 0.70) and it has no stand-up (walk.lua fallPolicy): a
-- fall ends its play, so the speeds stay under the limits.
return {
  head = {
    scan_pan = 1.0,            -- rad, half-range of the scan (the neck pan's reach: +-1.047)
    ground_z = -0.24,          -- m: the ground below the torso origin (torso frame), for look-at
    camera_z = 0.28,           -- m, the camera above the torso origin (look-at without a kinematic model)
  },

  body = {
    approach_speed = 0.14,     -- m/s (its walk makes 0.138 m/s of a 0.14 command)
    max_vx = 0.14,             -- m/s
    max_vy = 0.05,             -- m/s: the walk's limit
    max_va = 0.5,              -- rad/s: the walk's limit
    search_back_speed = 0.05,  -- m/s (the walk's limit backwards: 0.06)
    follow_speed = 0.12,       -- m/s
    -- the ball this far ahead of the torso when lined up: the neck's 45 deg and the torso's lean
    -- put the bottom of the camera's view ~0.21 m ahead of the torso origin on the ground, so the
    -- ball (0.14 m) is held further out than the toe (0.068 m) alone would ask, where the camera
    -- still sees most of it
    kick_x = 0.24,             -- m
    kick_y = 0.045,            -- m: the sole's centre out from the middle (walk.lua footY)
    -- no kick of its own: the OP3's standing kick (Config/common/walk.lua) throws it over (ROBOT=hoap3
    -- Tests/motion/sim_walk_test.sh kick: a fall, the toe at 0.40 m/s, the ball moved 0.13 m) and a
    -- fall ends its play; it walks the ball into the goal
    use_kick = false,
    align = { vx = { -0.05, 0.12 }, max_va = 0.4 },
    nav = { min_vx = -0.06 },  -- m/s: the walk's limit backwards
    dribble = {
      speed = 0.14,            -- m/s forward
      -- dead bands before slowing (the OP3's): without them the estimate's jitter and the push's
      -- sway kept its dribble at 0.09 m/s of the 0.14
      slow_side = 0.05,        -- m
      slow_angle = 0.15,       -- rad
      max_va = 0.3,            -- rad/s
    },
  },
}
