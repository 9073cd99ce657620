-- The head camera of the real robots: a UVC webcam read through V4L2 (Modules/camera).
-- Vertical field of view: OP3 (Logitech C920) 43.3 deg; DARwIn-OP (Logitech C905) about 47.5 deg
-- (focal length 545.6 px at 640 px wide, as published for its vision code).
local op3 = (os.getenv('OP_ROBOT') or 'darwin') == 'op3'
return {
  driver = 'v4l2',
  device = '/dev/video0',
  width = 640, height = 480,    -- px, YUYV
  fps = 30,
  fovy = math.rad(op3 and 43.3 or 47.5),
  nbuffers = 4,
  reopen_interval = 1.0,        -- s between attempts to reopen a missing or unplugged camera
  seed = 1,                     -- (dummy driver only)
  head_joint = { 0, 1 },        -- 0-based indices of head_pan, head_tilt in the joint order
  -- exposure, gain, white_balance (K), brightness, contrast, saturation; -1 = automatic; absent = as the
  -- camera has them. Fix exposure and white balance at the venue so the colour table stays valid.
  controls = {},
}
