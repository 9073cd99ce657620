-- The whole vision pipeline per frame on one core, on frames the sim renders (the field with lines,
-- goals, other robots and the ball; build/bin/sim_ball_frames, a seed of its own): camera pose from
-- the kinematics, the colour table's labels and blocks, the field boundary, the ball (the orange
-- one from the colour table, or the white one: candidates and the classifier), goal posts and
-- robots. Prints frames per second for each ball kind, side by side: per second of this process's
-- CPU time (os.clock: what one core does, whatever else the machine runs) and of wall time.
--   luajit Tools/bench/vision_detect.lua FRAMES [seconds]
local Config = require('Config')
local kinematics = require('kinematics')
local pipeline = require('Vision.pipeline')
local frames = require('Tools.ball_train.frames')
local shm = require('shm')
local ffi = require('ffi')

local path, seconds = arg[1], tonumber(arg[2]) or 2
assert(path, 'usage: vision_detect.lua FRAMES [seconds]')
local model = assert(kinematics.load())
local q, rpy, pose = {}, { 0, 0 }, { 0, 0, 0, R = {}, height = 0 }
for i = 1, #model.joints do q[i] = 0 end

-- the frames in memory, each with its own copy of the pixels and pose
local list = {}
local file = assert(frames.open(path))
for fr in file:each() do
  local f = { width = fr.width, height = fr.height, yuyv = ffi.new('uint8_t[?]', fr.width * fr.height * 2),
              pose = { fr.pose[1], fr.pose[2], fr.pose[3], R = {}, height = fr.pose.height } }
  ffi.copy(f.yuyv, fr.yuyv, fr.width * fr.height * 2)
  for i = 1, 9 do f.pose.R[i] = fr.pose.R[i] end
  list[#list + 1] = f
end

for _, kind in ipairs({ 'orange', 'white' }) do
  local vcfg, ccfg = Config.load('vision'), Config.load('camera')
  vcfg.ball.kind = kind
  local vp = assert(pipeline.new(vcfg, ccfg, model))
  local n, balls, robots, cands = 0, 0, 0, 0
  local t0, c0 = shm.C.shm_now(), os.clock()
  local t
  repeat
    for _, f in ipairs(list) do
      model:camera_pose(q, rpy, pose)          -- its cost counts; the frame's own pose is used
      local det = vp:detect(f, f.pose)
      n = n + 1
      if det.ball.detected then balls = balls + 1 end
      robots = robots + det.robots.n
      cands = cands + (vp.bd.ncand or 0)
    end
    t = os.clock()
  until t - c0 >= seconds
  local wall = shm.C.shm_now() - t0
  print(string.format('whole pipeline, %s ball, 640x480, one core: %.0f fps of CPU time (%.3f ms/frame; %.0f fps of '
    .. 'wall time) over %d rendered frames; per frame %.2f balls, %.2f robots, %.1f ball candidates classified', kind,
    n / (t - c0), 1e3 * (t - c0) / n, n / wall, #list, balls / n, robots / n, cands / n))
end
