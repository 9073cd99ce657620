-- The head camera (read by the vision process through Lib/camera.lua). Under Sim the frames come
-- from the sim DCM (Config/Sim/sim.lua's camera section renders them into camera.image).
return {
  driver = 'sim',               -- 'sim' | 'v4l2' | 'dummy'
  device = '/dev/video0',       -- v4l2 only
  width = 640, height = 480,    -- px, YUYV
  fps = 30,                     -- frames per second
  fovy = math.rad(43.3),        -- rad, vertical field of view (OP3)
  nbuffers = 4,                 -- v4l2 mmap buffers
  reopen_interval = 1.0,        -- s between attempts to reopen a missing camera
  seed = 1,                     -- dummy driver's random seed
  head_joint = { 0, 1 },        -- 0-based indices of head_pan, head_tilt in the joint order
  -- v4l2 controls (absent: left as the camera has them; -1: automatic exposure/white balance)
  controls = {},
}
