-- Vision: colour classes, lookup table, detection thresholds (Player/Vision, Run/lut_tool).
-- Colours are boxes in YUV (BT.601 full range, 0..255) that Run/lut_tool and the vision process
-- turn into a lookup table when no trained table is given. The sim renders a green carpet, white
-- lines and goals, and an orange ball.
return {
  lut = false,                  -- path of a LUT file (relative to the repo root), or false: from colors
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
    min_height = 4,             -- block pixels (8 px of the frame each)
    min_ratio = 2.5,            -- height / width of the post's region, block pixels
  },
  publish_labels = false,       -- write label images to shm for debugging
}
