-- Behavior parameters (Player/Behavior, World, HeadFSM, BodyFSM, GameFSM), defaults for every body;
-- a body changes what depends on its size in Config/robots/<ROBOT>/behavior.lua, a venue sets the
-- team and player numbers in its site folder (Config/site/behavior.lua or $HRP_SITE).
-- Units: metres, seconds, radians. Everything here can be changed while the robot runs (the
-- behavior process re-reads nothing by itself; restart it, or set fields from the REPL).
return {
  -- the robot's team and number, as the GameController knows them (set per robot in the site folder;
  -- the GameController's own settings and the rules: Config/common/game.lua)
  team_number = 1,
  player_number = 1,
  -- a behavior process that starts within `within` s (robot clock) of its predecessor's last world
  -- and game update (run_main restarted on a robot nobody carried) continues its game state and
  -- pose belief (the particles spread by `spread` m / rad around it) instead of starting afresh
  resume = { within = 3.0, spread = 0.1 },
  -- behavior steps: one every `step_ticks` DCM ticks
  step_ticks = 3,
  -- stop walking when the vision block has not been updated for this long (s, robot clock)
  vision_stale_after = 1.0,

  world = {
    seed = 1,
    field = { length = 9.0, width = 6.0, goal_width = 2.6 },
    ball = {
      process_noise = 0.5,     -- m/s^2
      meas_noise = 0.08,       -- m per m of range
      deceleration = 0.6,      -- m/s^2, rolling resistance (a size-1 ball on artificial turf)
      friction = 0.1,          -- 1/s, drag: the speed's decay on top of that
      max_speed = 5.0,         -- m/s
      reset_after = 2.0,       -- s without a sighting: the next one restarts the filter
      jump_distance = 0.6,     -- m: a sighting this far off restarts the filter
    },
    pose = {
      particles = 300,
      prior = { -4.5, 0.0, -3.0, 3.0 }, -- xmin, xmax, ymin, ymax: the robot starts in its own half
      odom_trans_noise = 0.15,  -- fraction of distance walked
      odom_rot_noise = 0.1,     -- fraction of angle turned
      odom_rot_per_m = 0.05,    -- rad per m walked
      post_range_noise = 0.15,  -- fraction of range
      post_bearing_noise = 0.12, -- rad
      outlier = 0.05,
      inject_fraction = 0.01,
      roughen_position = 0.03, -- m, spread added after resampling
      roughen_angle = 0.02,     -- rad
      reset_below = 0.25,       -- confidence under which two-post sightings re-seed particles
      reset_fraction = 0.05,
      project_fraction = 0.05,  -- share of particles moved onto a single post's sighting (sensor resetting)
      project_lost = 0.3,       -- ... when the belief is weak or contradicted
      project_max_jump = 1.0,   -- m: a particle moved onto a sighting goes at most this far
      gate_confidence = 0.6,    -- a belief this confident ignores a sighting ...
      gate_fit = 0.01,          -- ... that it explains this badly (mean likelihood)
      margin = 0.5,             -- m the robot may be outside the field lines
      -- the side (Player/World/pose_filter.lua): a belief this confident, its mirror impossible,
      -- sets the side's heading; a hypothesis further from it than side_tolerance (rad) is the mirror
      side_confidence = 0.5,
      side_tolerance = 1.57,
      own_half_margin = 0.3,    -- m past the halfway line a robot placed in its own half may be believed
      -- where the robot is placed before a half (World.world placement_lines): 'anywhere' in the own
      -- half, on a 'touchline' of it facing in, or on the 'left' / 'right' one (seen from the own
      -- goal in the first half; the sim's referee places team 1 on the right, team 2 on the left)
      placement = 'anywhere',
    },
    localised_confidence = 0.5, -- pose confidence from which the robot attacks (below: looks for goals)
    ball_lost_after = 4.0,      -- s without a sighting: the ball is lost (a look around takes 2)
    max_odometry_step = 0.5,    -- m: a larger jump means the motion process restarted
    post_min_range = 0.5,       -- m: nearer post sightings are false (a robot cannot stand there)
    post_max_range = 10.5,      -- m: further sightings are not used (vision: range error <= 3.2% to 9 m)
    post_pair_tolerance = 0.8,  -- m: two posts whose spacing is further off the goal's width are ignored
    imu_yaw = true,             -- turn between steps from the IMU's yaw changes, not the walk's plan
    -- other robots seen (Player/Vision/robots.lua) as obstacles, robot frame, moved by odometry
    obstacles = {
      memory = 4.0,             -- s in the camera's view without a sighting: forgotten (a scan looks away ~2 s)
      -- s without a sighting at all: forgotten, also out of the camera's view (a robot walked past,
      -- beside or behind: a walking robot moves ~1 m in this time, a standing one stays)
      memory_out_of_view = 10.0,
      merge = 0.5,              -- m: a sighting this near an obstacle is that obstacle
      blend = 0.5,              -- share of a new sighting in the obstacle's position
      field_margin = 0.5,       -- m: sightings the pose puts further off the field are not robots
      min_range = 0.3,          -- m: nearer sightings are the robot's own feet and arms
      max = 8,                  -- obstacles kept (the world block holds 8)
    },
  },

  -- the head and body machines' timing, game and field numbers, and the defaults of a kid-size body
  -- (the OP3's and DARwIn-OP's common numbers): a body changes what depends on its size (how far it
  -- looks, where it stands to kick, how fast it goes) in Config/robots/<ROBOT>/behavior.lua
  head = {
    scan_distances = { 2.5, 0.45 }, -- m: the scan's far and near rows (ground distance looked at)
    turning_row_time = 0.0,    -- s on each row while the body turns on the spot to search, the
                               -- head looking ahead (0: the scan's sweeps)
    scan_near_first = 1.0,     -- m: a ball lost nearer than this is looked for where it was first
    scan_swing = 0.4,          -- rad, the head's swing around a ball lost near the feet
    goal_look_distance = 3.0,  -- m: a goal out of the head's reach is looked for this far on its side
    scan_period = 4.0,         -- s per sweep
    scan_near_time = 1.5,      -- s looking for a ball lost near the feet where it was first
    track_gain = 0.6,          -- fraction of the angle error closed per step
    look_goal_every = 6.0,     -- s between looks at the goal while tracking (dribbling too: the
                               -- pose drifts ~15% of the distance walked between post sightings)
    look_goal_every_near = 3.0, -- s, ... within near_goal of the opponent goal
    near_goal = 2.5,           -- m
    look_goal_every_lost = 1.5, -- s, ... while the pose is not trusted (a sweep each time)
    look_goal_time = 1.2,      -- s looking where the goal should be
    look_around_time = 2.0,    -- s for one sweep across the head's range
  },

  body = {
    search_turn_speed = 0.5,   -- rad/s
    search_look_time = 0.0,    -- s standing while the head sweeps once before turning (0: turn at once)
    search_back_near = 0.5,    -- m: a ball lost nearer than this: step back first
    search_back_speed = 0.08,  -- m/s
    approach_behind = 0.30,    -- m: aim at this point behind the ball (away from the goal)
    -- a ball in a goal is scored: the robot stands where it is (BodyFSM/wait.lua) instead of following it into
    -- the net, where it falls (the fall census, docs/results/game.md). In the goal: its estimate `beyond` m
    -- past a goal line (more than the ball's radius, 0.07 m, and a pose estimate's usual error along the
    -- field: a ball on the line is still pushed over it) and `inside` m within the posts (a ball beside a post
    -- is still played); the robot waits `wait` s at most (a wrong pose, a mirrored one, puts a ball there
    -- too), then plays on and waits again only `retry` s later
    ball_in_goal = { beyond = 0.15, inside = 0.2, wait = 10, retry = 30 },
    align_distance = 0.45,     -- m: from here on, align precisely ...
    approach_near = 0.1,       -- m: ... once this much nearer (approach -> align)
    align_far = 0.3,           -- m: back to approaching this much further (align -> approach)
    kick_tolerance_x = 0.05,   -- m: the ball this near the kicking spot, ahead ...
    kick_tolerance_y = 0.04,   -- m: ... and sideways
    kick_side_switch = 0.05,   -- m: the ball this far on the other side: kick with the other foot
    -- aligning: velocity from the error to the kicking spot (ahead, sideways, heading)
    align = {
      gain = { 0.7, 0.7, 0.8 }, -- 1/s: vx, vy per m of error, va per rad
      sideways_per_turn = 0.15, -- m/s of side-step per rad of heading error (circling the ball)
      vx = { -0.06, 0.12 },    -- m/s
      max_va = 0.5,            -- rad/s
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
      -- stepping around another robot in the way (BodyFSM/nav.lua avoid): a robot nearer the straight
      -- path than `clearance` m (its foot point: its nearest edge; both bodies' half widths and a
      -- margin), from `behind` m behind to `short` m before the target, is passed along the tangent
      -- to that circle turned out by `margin` rad; not within `min_distance` m of the target;
      -- teammates from their messages too, heard within `mate_age` s (a walking robot moves ~0.1 m
      -- in the message period, 0.5 s)
      avoid = { clearance = 0.55, behind = 0.1, short = 0.2, margin = 0.15, min_distance = 0.5, mate_age = 1.0 },
    },
    follow_turn_gain = 0.8,    -- 1/s: turning towards the ball's bearing after a kick
    reposition_near = 1.0,     -- m: the ball's last estimate this near: search (the head sees it from here)
    wander_arrive = 0.3,       -- m: at the wander point
    max_vx = 0.3, max_vy = 0.1, -- m/s: the body's fastest commands (its max_va: the body's file)
    search_turn_time = 8.0,    -- s turning on the spot before wandering
    search_back_time = 2.0,    -- s stepping back from a ball lost at the feet
    relocalise_below = 0.3,    -- pose confidence under which the robot stops attacking to localize
    localize_turn_after = 5.0, -- s standing (the head looking around) before turning on the spot
    localize_timeout = 12.0,   -- s: then go on with the best guess ...
    localize_retry_after = 15.0, -- s ... for at least this long
    wander_time = 6.0,         -- s walking towards the field's centre before turning again
    kick_tolerance_angle = 0.25, -- rad: facing the goal within this
    align_timeout = 12.0,      -- s: give up aligning and just walk into the ball
    kick_timeout = 4.0,        -- s waiting for the kick to finish
    use_kick = true,           -- false: dribble the ball into the goal
    -- walking the ball to the goal instead of kicking (the body's distances and speeds for it: its
    -- behavior.lua)
    dribble = {
      enabled = true,
      start_angle = 0.3,         -- rad: attack direction this near to straight ahead to start
      max_angle = 0.8,           -- rad: attack direction this far off: align again
      start_side = 0.06,         -- m: ball this near the centre line ahead of the feet to start ...
      start_ahead = 0.1,         -- m: ... and this near the kicking spot along x (behind it) ...
      start_far = 0.1,           -- m: ... or this far ahead of it (further: walk into the dribble at speed)
      max_side = 0.16,           -- m: the ball this far to the side: align again
      max_ahead = 0.6,           -- m: the ball this far ahead: approach again
      min_ahead = 0.02,          -- m: the ball nearer (under the feet, behind): align again
      fresh_age = 0.3,           -- s: a ball seen longer ago (the head looking at the goal) is taken
                                 -- to roll on ahead: the three tests above wait for a new sighting
      stale_age = 2.0,           -- s: a ball not seen for this long (a look at the goal takes 1.2 s): align again
      hint_ahead = 0.25,         -- m: ... and the head looks for it this far ahead of the torso (where
                                 -- the pushed ball rolls; the stale estimate falls behind the feet)
      slow_min = 0.3,            -- the least fraction of speed kept for a ball off to the side
      slow_side = 0.0,           -- m: the ball further off the centre line than this slows the walk ...
      slow_angle = 0.0,          -- rad: ... and so does the goal further off the heading than this
      side_gain = 1.0,           -- 1/s: side-step per m of the ball's sideways offset
      side_per_turn = 0.1,       -- m/s of side-step per rad of attack direction error
      turn_gain = 0.8,           -- 1/s
      ball_turn_gain = 0.0,      -- 1/s: turning per rad of the ball's bearing (towards a ball off centre)
      max_va = 0.4,              -- rad/s
      -- another robot in the lane ahead of the ball (within `avoid_ahead` m, nearer its line to the
      -- goal than `avoid_lane` m: both half widths and the ball's) is passed: the aim turned to its
      -- side, by the angle that clears it by the lane, at most `avoid_angle` rad (under max_angle:
      -- the dribble goes on)
      avoid_ahead = 1.2, avoid_lane = 0.45, avoid_angle = 0.45,
    },
    -- shooting with a kick out of the walk (Player/BodyFSM/shot.lua, kick.lua): off by default (a
    -- body whose walk config has walkKick turns it on in its behavior.lua, with its kick zone)
    walk_kick = {
      enabled = false,
      x = { 0.15, 0.28 },      -- m: the ball's centre this far ahead of the torso ...
      y = { 0.02, 0.11 },      -- m: ... and this far to the side (of the kicking foot)
      max_age = 0.5,           -- s: the ball seen this recently
      max_angle = 0.3,         -- rad: the goal's direction from the ball this near the heading ...
      margin = 0.3,            -- m: ... and within the goal's mouth less this margin each side
      x_far = 0.0,             -- m: a ball up to this beyond x[2] is taken too (the body's walk
                               -- kick waits for a step near enough: walkKick.<kind>.ballMax)
      max_range = 6.0,         -- m: the goal this near
      max_vy = 0.03,           -- m/s: the walk's sideways speed at most this ...
      max_va = 0.2,            -- rad/s: ... and its turning
      speed = 0.08,            -- m/s: walking on straight while the kick is asked for and made
      max_vx = 0.13,           -- m/s: the kick is asked for once the walk is this slow
      timeout = 2.0,           -- s waiting for the kick
      close_gain = 0.0,        -- 1/s: the walk closes on a ball beyond x[2] before slowing (0: slows at once)
      follow = false,          -- the request asked again each tick with the ball's fresh place until its step
      keep_ball = false,       -- the head stays on the ball meanwhile (no look at the goal)
    },
    attack_depth = 0.5,        -- m behind the goal line: the point aimed at
    dribble_distance = 1.2,    -- m: nearer than this to the goal line, walk the ball in
    follow_time = 3.0,         -- s walking after the ball following a kick ...
    follow_speed = 0.15,       -- m/s ... at most this fast (out of a kick step out of the walk a
                               -- start at the approach speed threw the OP3 over in the scoring runs)
    reposition = { -1.5, 0.0 }, -- field point to walk to when the ball is lost
    reposition_timeout = 10.0, -- s walking back towards the ball's last estimate before searching
  },

  ready_pose = { -1.0, 0.0, 0.0 }, -- where the robot walks in the ready state (field frame)
  ready_tolerance = { 0.2, 0.2 },  -- m, rad: there when this near to ready_pose and turned to it
}
