-- The head camera (read by the vision process through Lib/camera.lua): a UVC webcam through V4L2 on
-- a real robot; Config/platforms/Sim/camera.lua switches to the frames the sim DCM renders. The
-- field of view is the body's (Config/robots/<ROBOT>/camera.lua).
return {
  driver = 'v4l2',              -- 'sim' | 'v4l2' | 'dummy'
  device = '/dev/video0',       -- v4l2 only
  width = 640, height = 480,    -- px, YUYV
  fps = 30,                     -- frames per second
  nbuffers = 4,                 -- v4l2 mmap buffers
  reopen_interval = 1.0,        -- s between attempts to reopen a missing camera
  seed = 1,                     -- dummy driver's random seed
  head_joint = { 0, 1 },        -- 0-based indices of head_pan, head_tilt in the joint order
  -- s the shutter is open. A frame carries the head and torso angles of its exposure's end, but a
  -- moving camera smears the image over the whole exposure, so what the vision finds in it (a
  -- ball's centre) was seen from the pose at the exposure's middle: the vision takes the angles
  -- back by half this at their rate between the last two frames (Vision.pipeline). It must be the
  -- camera's: controls.exposure (100 us units) on a real one, the sim's camera.exposure
  -- (Config/platforms/Sim/sim.lua) in the sim. 0: the angles as the frame has them.
  exposure_time = 0.010,
  -- v4l2 controls (absent: left as the camera has them; -1: automatic exposure/white balance)
  -- exposure, gain, white_balance (K), brightness, contrast, saturation; -1 = automatic; absent = as the
  -- camera has them. Fix exposure and white balance at the venue so the colour table stays valid.
  controls = {},
}
