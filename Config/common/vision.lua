-- Vision: colour classes, lookup table, detection thresholds (Player/Vision, Run/lut_tool).
-- Colours are boxes in YUV (BT.601 full range, 0..255) that Run/lut_tool and the vision process
-- turn into a lookup table when no trained table is given. The sim renders a green carpet, white
-- lines and goals, and an orange ball.
return {
  lut = false,                  -- path of a LUT file (relative to the repo root), or false: from colors
                                -- (a venue's trained table: set it in the site folder's vision.lua)
  scale = 2,                    -- label image = frame subsampled by 2 (320x240)
  block = 4,                    -- block image = 4x4 bit-OR of the label image (80x60)
  -- bit: the colour's label bit; y/u/v: {min, max}; display: RGB for label renderings
  colors = {
    { name = 'orange', bit = 1, y = { 40, 235 }, u = { 0, 112 }, v = { 168, 255 },
      display = { 255, 128, 0 } },
    { name = 'green', bit = 8, y = { 30, 190 }, u = { 56, 124 }, v = { 40, 122 },
      display = { 0, 160, 0 } },
    { name = 'white', bit = 16, y = { 172, 255 }, u = { 104, 152 }, v = { 104, 152 },
      display = { 255, 255, 255 } },
    -- the teams' jerseys (the sim's red: Y 83, U 107, V 212; blue: Y 72, U 195, V 98, sim.lua's `teams`)
    { name = 'red', bit = 2, y = { 30, 170 }, u = { 95, 125 }, v = { 185, 245 },
      display = { 220, 30, 45 } },
    { name = 'blue', bit = 4, y = { 25, 160 }, u = { 165, 230 }, v = { 60, 125 },
      display = { 30, 70, 190 } },
  },
  ball = {
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
  -- other robots: non-field runs standing on the field (Player/Vision/robots.lua)
  robots = {
    field = 24,                 -- label bits that are field, never a robot: green | white
    teams = { [0] = 4, [1] = 2 }, -- jersey label bits by the GameController's colour: 0 blue, 1 red
    column_step = 2,            -- label columns between the columns looked at
    min_run = 3,                -- label pixels in a row that start a robot (noise is single pixels)
    gap = 3,                    -- field pixels bridged going up a robot (legs apart)
    min_height = 0.25,          -- m above the ground its run reaches (the ball is 0.14 m)
    max_range = 3.0,            -- m: further robots are not looked for (too few pixels to trust)
    join = 0.35,                -- m between neighbouring columns' feet of one robot
    min_width = 0.06,           -- m: narrower is a post's shadow or noise
    max_width = 1.2,            -- m: wider is not one robot (or two side by side)
    min_team_pixels = 6,        -- label pixels of a jersey colour that name the team
    max_robots = 4,             -- reported, nearest first (the vision block holds 4)
  },
  publish_labels = false,       -- write label images to shm for debugging
}
