-- Vision: colour classes, lookup table, detection thresholds (Player/Vision, Run/lut_tool).
-- Colours are boxes in YUV (BT.601 full range, 0..255) that Run/lut_tool and the vision process
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
  -- bit: the colour's label bit; y/u/v: {min, max}; display: RGB for label renderings
  colors = {
    { name = 'orange', bit = 1, y = { 40, 235 }, u = { 0, 92 }, v = { 168, 255 },
      display = { 255, 128, 0 } },
    { name = 'green', bit = 8, y = { 30, 190 }, u = { 56, 124 }, v = { 40, 122 },
      display = { 0, 160, 0 } },
    { name = 'white', bit = 16, y = { 140, 255 }, u = { 106, 135 }, v = { 106, 150 },
      display = { 255, 255, 255 } },
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
  publish_labels = false,       -- write label images to shm for debugging
}
