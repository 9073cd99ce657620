-- The Hubo2+'s sizes and speeds for the behavior (Player/BodyFSM, HeadFSM; overlaid on
-- Config/common/behavior.lua). Nothing asks the Hubo to play football: these are the OP3's numbers
-- (Config/robots/op3/behavior.lua) with the ones that depend on the body changed, so that the
-- behavior process runs on it: the torso origin 0.69 m up when walking, the camera 0.52 m above it,
-- a head that tilts +-30 deg and does not pan (its scan is the waist's business: not done), the
-- walk's speeds (Config/robots/hubo2plus/walk.lua). Units: m, s, rad.
return {
  head = {
    scan_pan = 0.4,            -- rad, half-range of the scan (the head pan's reach)
    scan_distances = { 2.5, 0.45 }, -- m: the scan's far and near rows (ground distance looked at;
                               -- the camera's 43 deg view covers 0.2-1.0 m and 0.7 m-horizon)
    scan_near_first = 1.0,     -- m: a ball lost nearer than this is looked for where it was first
    scan_swing = 0.4,          -- rad, the head's swing around a ball lost near the feet
    goal_look_distance = 3.0,  -- m: a goal out of the head's reach is looked for this far on its side
    ground_z = -0.69,          -- m: the ground below the torso origin (torso frame), for look-at
    camera_z = 0.52,            -- m, the camera above the torso origin (look-at without a kinematic model)
  },

  body = {
    search_turn_speed = 0.5,   -- rad/s
    search_back_near = 0.5,    -- m: a ball lost nearer than this: step back first
    search_back_speed = 0.08,  -- m/s
    approach_speed = 0.25,     -- m/s
    approach_behind = 0.30,    -- m: aim at this point behind the ball (away from the goal)
    align_distance = 0.45,     -- m: from here on, align precisely ...
    approach_near = 0.1,       -- m: ... once this much nearer (approach -> align)
    align_far = 0.3,           -- m: back to approaching this much further (align -> approach)
    kick_x = 0.30,             -- m: ball this far ahead of the torso when kicking
    kick_y = 0.06,             -- m: ball this far to the side (towards the kicking foot)
    kick_tolerance_x = 0.05,
    kick_tolerance_y = 0.04,
    kick_side_switch = 0.05,   -- m: the ball this far on the other side: kick with the other foot
    -- aligning: velocity from the error to the kicking spot (ahead, sideways, heading)
    align = {
      gain = { 0.7, 0.7, 0.8 }, -- 1/s: vx, vy per m of error, va per rad
      sideways_per_turn = 0.15, -- m/s of side-step per rad of heading error (circling the ball)
      vx = { -0.06, 0.12 },    -- m/s
      max_va = 0.5,            -- rad/s
    },
    -- walking the ball to the goal instead of kicking (the kick moves the ball < 1 m in the sim)
    dribble = {
      start_side = 0.06,         -- m: ball this near the centre line ahead of the feet to start ...
      start_ahead = 0.1,         -- m: ... and this near the kicking spot along x
      max_side = 0.16,           -- m: the ball this far to the side: align again
      max_ahead = 0.6,           -- m: the ball this far ahead: approach again
      min_ahead = 0.02,          -- m: the ball nearer (under the feet, behind): align again
      speed = 0.25,              -- m/s forward
      slow_min = 0.3,            -- the least fraction of speed kept for a ball off to the side
      side_gain = 1.0,           -- 1/s: side-step per m of the ball's sideways offset
      side_per_turn = 0.1,       -- m/s of side-step per rad of attack direction error
      turn_gain = 0.8,           -- 1/s
      max_va = 0.4,              -- rad/s
    },
    -- walking to a point (Player/BodyFSM/nav.lua)
    nav = {
      pass_along = 0.15,       -- m: the ball less far ahead along the attack line: pass beside it ...
      pass_side = 0.45,        -- m: ... this far to the side of it ...
      pass_behind = 0.5,       -- ... aiming at this fraction of approach_behind behind it
      near = 0.6,              -- m: nearer, turn to the wanted heading while side-stepping
      far_turn_gain = 1.2,     -- 1/s: va per rad of bearing, far away
      far_side_gain = 0.3,     -- 1/s: vy per m sideways, far away
      near_turn_gain = 1.0,    -- 1/s, near
      near_gain = 0.8,         -- 1/s: vx, vy per m, near
      min_vx = -0.1,           -- m/s: the fastest backwards
    },
    follow_turn_gain = 0.8,    -- 1/s: turning towards the ball's bearing after a kick
    reposition_near = 1.0,     -- m: the ball's last estimate this near: search (the head sees it from here)
    wander_arrive = 0.3,       -- m: at the wander point
    max_vx = 0.3, max_vy = 0.1, max_va = 0.5,
  },
}
