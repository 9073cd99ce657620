-- Vision: colour classes, lookup table, detection thresholds (Player/Vision, Tools/lut).
-- Colours are boxes in YUV (BT.601 full range, 0..255) that Tools/lut and the vision process
-- turn into a lookup table when no trained table is given. The sim renders a green carpet, white
-- lines and goals, and an orange ball (U 52, V 214); orange's U ends at 92 so that the red team's
-- jerseys (U 107, Config/platforms/Sim/sim.lua `teams`) are not taken for the ball. White starts at
-- Y 140: a post's side away from the light renders at 0.75 of 235 (176), and the sim camera's realism
-- (sim.lua camera.realism: -10% light across the field, -6% exposure drift, noise) takes it to ~145;
-- its U ends at 135, below the backdrop's (139), which is as bright then.
return {
  lut = false,                  -- path of a LUT file (relative to the repo root), or false: from colors
                                -- (a venue's trained table: set it in the site folder's vision.lua)
  scale = 2,                    -- label image = frame subsampled by 2 (320x240)
  block = 4,                    -- block image = 4x4 bit-OR of the label image (80x60)
  -- The camera's pose tilts with the torso's roll and pitch from the IMU as they were at the frame's
  -- capture (the frame's angle: dcm.sensor's angle at the exposure, as its head angles); false: the
  -- torso taken as upright (the seed's way, for a body without an IMU). Walking, the OP3's torso
  -- pitches by up to 5 deg: upright, its ball range was off by 30% on average (Tools/bench/walk_eye.sh);
  -- with the angles 32 ms late (at the frame's delivery) by 1.8%, at the exposure by 1.0%.
  imu_tilt = true,
  -- bit: the colour's label bit; y/u/v: {min, max}; display: RGB for label renderings
  colors = {
    { name = 'orange', bit = 1, y = { 40, 235 }, u = { 0, 92 }, v = { 168, 255 },
      display = { 255, 128, 0 } },
    { name = 'green', bit = 8, y = { 30, 190 }, u = { 56, 124 }, v = { 40, 122 },
      display = { 0, 160, 0 } },
    { name = 'white', bit = 16, y = { 140, 255 }, u = { 106, 135 }, v = { 106, 150 },
      display = { 255, 255, 255 } },
    -- the teams' jerseys (the sim's: Config/platforms/Sim/sim.lua teams; red U 107 V 212, blue U 195 V 98)
    { name = 'red', bit = 2, y = { 30, 200 }, u = { 96, 124 }, v = { 180, 245 }, display = { 220, 30, 45 } },
    { name = 'blue', bit = 4, y = { 30, 200 }, u = { 170, 230 }, v = { 60, 124 }, display = { 30, 70, 190 } },
  },
  ball = {
    kind = 'orange',            -- 'orange': the colour table's ball (below); 'white': the FIFA ball, found
                                -- by candidates and a classifier (white, below)
    white = {
      model = 'Config/common/ball_white.mlp', -- the classifier (trained by Tools/ball_train/train.sh)
      green = 8,                -- label bits of the field
      boundary_run = 4,         -- label rows of field that start the field in a column
      step = 2,                 -- label px between candidate positions
      min_inner = 0.75,         -- fraction of not-field labels inside the ball's expected disc, at least
      max_ring = 0.45,          -- fraction of not-field labels in the ring around it, at most
      min_radius = 4,           -- px, the smallest ball looked for (about 5 m away)
      max_candidates = 8,       -- candidates the classifier checks per frame, best shapes first
      threshold = 0.98,         -- classifier probability for a ball (chosen on frames of seed 21: neither
                                -- the training seeds nor the tests')
    },
    color = 1,                  -- label bit
    diameter = 0.14,            -- m
    min_area = 4,               -- label pixels
    min_fill = 0.45,            -- area / bounding box area
    max_aspect = 2.2,           -- bounding box long side / short side (partly hidden balls)
    green_below = 0.1,          -- fraction of field pixels needed in the band below the ball (0: off)
    green_color = 24,           -- label bits that count as field below the ball: green | white (lines)
    max_range = 6.0,            -- m, farther detections are refused
    size_tolerance = 2.0,       -- range from size within this factor of the ground-projected range
  },
  -- other robots: bands of label columns neither field nor line that rise from a foot on the field
  -- to the field boundary (Player/Vision/detect_robots.lua)
  robots = {
    enabled = true,
    field = 25,                 -- label bits of field, lines and the orange ball (green | white | orange):
                                -- not a robot
    red = 2, blue = 4,          -- label bits of the team colours (colors above)
    min_run = 6,                -- label rows of a column's run, at least...
    min_below = 5,              -- ... of them below the field boundary
    max_gap = 3,                -- field or line labels bridged inside a run (the field seen between legs)
    leg_gap = 16,               -- label rows between a short run and the run above it that still make one
                                -- column (legs blurred into the field's colour above the feet)
    min_width = 3,              -- label columns of a band, at least (and the columns bridged inside one)
    merge_gap = 0.12,           -- m between neighbouring bands at their range that still make one robot (legs)
    arm_width = 0.1,            -- m: a band no wider joins its neighbour whatever its foot (an arm)
    min_width_m = 0.08,         -- m, a band's width at its foot's range: at least (a leg)...
    max_width_m = 1.2,          -- ... and at most (two robots side by side)
    depth_offset = 0.06,        -- m from the front of the feet to the robot's middle, along the ray
    self_x = 0.25, self_y = 0.2, -- m: a foot point (robot frame) with x <= self_x and |y| <= self_y is the
                                -- own body (the op3's feet reach 0.12 m forward, its hands 0.15 m aside)
    height = 0.6,               -- m, a robot's height at most (the top of its box in the image)
    min_team = 6,               -- labels of a team colour in a band to name its team
    max_range = 6.0,            -- m
  },
  goal = {
    color = 16,                 -- label bit (white posts)
    green = 8,                  -- label bit of the field under a post's base
    diameter = 0.1,             -- m, of a post
    min_rise = 0.6,             -- m: a post's white run reaches this high above the ground (posts
                                -- are 1.2 m, the camera about 0.45 m: lines never rise at all)
    min_rows = 6,               -- label rows of a post's white run, at least
    gap = 2,                    -- label pixels of noise bridged inside a post's run
    width_tolerance = { 0.5, 1.8 }, -- post width in the image / width expected at its base's range
    max_range = 10.5,           -- m, farther posts are refused (the carpet's diagonal)
  },
  publish_labels = false,       -- write label images to shm for debugging
}
