-- The vision process's per-frame work in LuaJIT on one core: camera pose from the kinematics,
-- the colour pipeline (libhrpimg) and the ball and goal detectors, on a 640x480 YUYV field scene
-- (green carpet with noise, a white line, a white post, an orange ball). Prints frames per second.
--   luajit Tools/bench/vision_lua.lua [seconds]
local ffi = require('ffi')
local Config = require('Config')
local kinematics = require('kinematics')
local pipeline = require('Vision.pipeline')
local shm = require('shm')

local seconds = tonumber(arg[1]) or 2
local W, H = 640, 480
local vcfg, ccfg = Config.load('vision'), Config.load('camera')
local model = assert(kinematics.load())
local vp = assert(pipeline.new(vcfg, ccfg, model))

local project = require('Vision.project')
local q = {}
for i = 1, #model.joints do q[i] = 0 end
q[2] = -0.5
local rpy = { 0, 0 }
-- the ball drawn where the camera sees a ball 1.5 m ahead, 0.2 m left
local pose = model:camera_pose(q, rpy)
local cm = project.from_config(ccfg)
local bu, bv, depth = project.to_image(cm, pose, 1.5, 0.2, 0.07)
local br = cm.f * 0.07 / depth

local buf = ffi.new('uint8_t[?]', W * H * 2)
math.randomseed(1)
for y = 0, H - 1 do
  for x = 0, W - 1, 2 do
    local Y, U, V = 93, 98, 90
    local line = math.abs(y - (200 + (x - 320) / 6)) < 4 or (x > 60 and x < 84 and y < 260)
    if line then Y, U, V = 230, 128, 128 end
    if (x + 0.5 - bu) ^ 2 + (y + 0.5 - bv) ^ 2 < br * br then Y, U, V = 120, 52, 214 end
    local p = (y * W + x) * 2
    buf[p], buf[p + 1] = Y + math.random(-3, 3), U
    buf[p + 2], buf[p + 3] = Y + math.random(-3, 3), V
  end
end
local frame = { yuyv = buf, width = W, height = H, head = ffi.new('double[2]', 0, -0.5) }

local det = vp:process(frame, q, rpy)
local n, t0 = 0, shm.C.shm_now()
local t
repeat
  for _ = 1, 50 do vp:process(frame, q, rpy) end
  n = n + 50
  t = shm.C.shm_now()
until t - t0 >= seconds
print(string.format('vision process per frame (LuaJIT: camera pose + libhrpimg pipeline + ball/goal detection), '
  .. '640x480: %.0f fps (%.3f ms/frame); ball %s at %.2f, %.2f m, %d goal post(s)', n / (t - t0),
  1e3 * (t - t0) / n, det.ball.detected and 'seen' or 'not seen', det.ball.x or 0, det.ball.y or 0, det.goals.n))
