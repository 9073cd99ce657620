-- The vision process: grabs frames from the configured camera, runs the colour pipeline and the
-- detectors, and writes the `vision` block (Lib/Vision.lua reads it).
--
--   luajit Player/Vision/main.lua [--driver v4l2|dummy|sim] [--fps N] [--frames N] [--seconds S]
--                                 [--report S] [--quiet]
-- --driver/--fps override Config/<platform>/camera.lua (bring-up: --driver dummy --fps 0);
-- --frames/--seconds stop after that many frames / wall seconds (tests); --report prints a line
-- with frame counts, detections, errors and memory every S wall seconds.
-- A camera that is absent or lost is reported and retried; a bad frame is counted and skipped;
-- nothing in a frame can stop the process. In the sim's lockstep mode the process takes part in
-- the lockstep, so which frame is seen at which tick is deterministic.
local ffi = require('ffi')
local Config = require('Config')
local shm = require('shm')
local camera = require('camera')
local kinematics = require('kinematics')
local lockstep = require('lockstep')
local pipeline = require('Vision.pipeline')
local param = require('param')

local args = { ... }
local opts = { report = 0 }
do
  local i = 1
  while i <= #args do
    local a, v = args[i], args[i + 1]
    if a == '--driver' then opts.driver = v; i = i + 1
    elseif a == '--fps' then opts.fps = tonumber(v); i = i + 1
    elseif a == '--frames' then opts.frames = tonumber(v); i = i + 1
    elseif a == '--seconds' then opts.seconds = tonumber(v); i = i + 1
    elseif a == '--report' then opts.report = tonumber(v); i = i + 1
    elseif a == '--quiet' then opts.quiet = true
    else
      io.stderr:write('vision: unknown option ', tostring(a), '\n')
      os.exit(2)
    end
    i = i + 1
  end
end

local function log(fmt, ...)
  if not opts.quiet then io.stdout:write('[vision] ', string.format(fmt, ...), '\n'); io.stdout:flush() end
end

local vcfg = Config.load('vision', { scale = 'number', block = 'number', colors = 'table', imu_tilt = 'boolean',
  ball = { color = 'number', diameter = 'number', min_area = 'number', min_fill = 'number',
           max_aspect = 'number', green_below = 'number', max_range = 'number' },
  goal = { color = 'number', diameter = 'number', min_rise = 'number' } })
local ccfg = Config.load('camera', { driver = 'string', width = 'number', height = 'number',
  fps = 'number', fovy = 'number', intrinsics = { fx = 'number', fy = 'number', cx = 'number', cy = 'number' },
  distortion = { k1 = 'number', k2 = 'number' } })

-- the camera's settings with the command line's overrides
local cam_settings = {}
for k, v in pairs(ccfg) do cam_settings[k] = v end
cam_settings.driver = opts.driver or ccfg.driver
cam_settings.fps = opts.fps or ccfg.fps

local model = assert(kinematics.load())
local vp, err = pipeline.new(vcfg, ccfg, model)
if not vp then
  io.stderr:write('vision: ', err, '\n')
  os.exit(1)
end
local cam
cam, err = camera.open(cam_settings)
if not cam then
  io.stderr:write('vision: ', err, '\n')
  os.exit(1)
end

-- every Config value live (Lib/param.lua): the detectors read vision.ball / vision.goal at every
-- frame; what the pipeline derives at its creation (label and block images, the LUT) is rebuilt
local params_live = param.follow('vision')
local function rebuild(key)
  local fresh, perr = pipeline.new(vcfg, ccfg, model)
  if fresh then vp = fresh else log('%s: pipeline not rebuilt: %s', key, perr) end
end
for _, key in ipairs({ 'vision.scale', 'vision.block', 'vision.lut', 'vision.colors', 'camera.fovy',
                       'camera.intrinsics', 'camera.distortion', 'vision.ball.kind', 'vision.ball.white.model' }) do
  params_live:on(key, rebuild)
end
params_live:on('camera.fps', function(_, fps) cam_settings.fps = fps end)

local vision = shm.open('vision')
local sensor = shm.open('dcm.sensor')
local sync = shm.open('sync')
-- the sim camera's block is read in C (Modules/camera); opened here too, so that its replacement is seen
if cam.driver == 'sim' then shm.open('camera.image') end
-- a block replaced under this process (removed, or recreated with another layout): exit, named, for a restart
local check_blocks = require('shm_watch').exit_on_replaced('vision')
local njoint = sensor:count('position')

ffi.cdef [[ long sysconf(int name); ]]
local PAGE_KB = tonumber(ffi.C.sysconf(30)) / 1024   -- _SC_PAGESIZE

local function rss_kb()
  local f = io.open('/proc/self/statm', 'r')
  if not f then return 0 end
  local _, rss = f:read('*n', '*n')
  f:close()
  return (rss or 0) * PAGE_KB
end

local q, rpy = {}, { 0, 0 }
local counts = { frames = 0, detected = 0, bad_frames = 0, errors = 0, cam_errors = 0 }
local last_time, fps = nil, 0

local function read_body()
  local seq
  repeat
    seq = shm.C.shm_read_begin(sensor._handle)
    for i = 1, njoint do q[i] = sensor.position[i - 1] end
  until shm.C.shm_read_retry(sensor._handle, seq) == 0
end

-- (begin_write/end_write rather than a closure: keeps the per-frame path free of allocations)
local function publish(frame, det)
  local ball, goals, b = det.ball, det.goals, vision
  b:begin_write()
  b.frame[0] = frame.seq
  b.time[0] = frame.time
  b.ball_detected[0] = ball.detected and 1 or 0
  if ball.detected then
    b.ball_image[0], b.ball_image[1] = ball.u, ball.v
    b.ball_position[0], b.ball_position[1] = ball.x, ball.y
    b.ball_radius[0] = ball.radius
  end
  b.goal_posts[0] = goals.n
  for i = 1, goals.n do
    b.goal_position[2 * i - 2], b.goal_position[2 * i - 1] = goals[i].x, goals[i].y
  end
  b.ball_kind[0] = ball.kind
  b.ball_score[0] = ball.detected and ball.score or 0
  local robots = det.robots
  b.robots[0] = robots.n
  for i = 1, robots.n do
    local r, k = robots[i], 4 * (i - 1)
    b.robot_position[2 * i - 2], b.robot_position[2 * i - 1] = r.x, r.y
    b.robot_image[k], b.robot_image[k + 1], b.robot_image[k + 2], b.robot_image[k + 3] = r.u0, r.v0, r.u1, r.v1
    b.robot_team[i - 1] = r.team
    b.robot_foot_visible[i - 1] = r.foot_visible and 1 or 0
  end
  b.fps[0] = fps
  b:end_write()
end

-- the joint angles now (the legs: the camera's height, which changes little within a frame's
-- latency); the head's and the torso's tilt as at the capture, which the frame carries
local function process(frame)
  read_body()
  if vcfg.imu_tilt then rpy[1], rpy[2] = frame.angle[0], frame.angle[1] else rpy[1], rpy[2] = 0, 0 end
  local det, perr = vp:process(frame, q, rpy)
  if not det then
    counts.bad_frames = counts.bad_frames + 1
    if counts.bad_frames < 10 or counts.bad_frames % 1000 == 0 then
      log('bad frame %d: %s', frame.seq, perr)
    end
    return
  end
  if last_time and frame.time > last_time then
    fps = 0.9 * fps + 0.1 / (frame.time - last_time)
  end
  last_time = frame.time
  counts.frames = counts.frames + 1
  if det.ball.detected then counts.detected = counts.detected + 1 end
  publish(frame, det)
end

local last_err, last_err_count = nil, 0
local function camera_error(msg, code)
  if code == camera.ETIMEOUT and cam.driver == 'sim' then return end   -- between frames, or sim paused
  counts.cam_errors = counts.cam_errors + 1
  if msg ~= last_err or last_err_count % 100 == 0 then log('camera: %s', msg) end
  last_err_count = msg == last_err and last_err_count + 1 or 1
  last_err = msg
end

-- one frame (or a camera error), never raising
local function step(timeout)
  params_live:poll()
  local frame, msg, code = cam:grab(timeout)
  if not frame then
    camera_error(msg, code)
    return false
  end
  local ok, perr = pcall(process, frame)
  if not ok then
    counts.errors = counts.errors + 1
    if counts.errors < 10 or counts.errors % 1000 == 0 then log('error on frame %d: %s', frame.seq, perr) end
  end
  return true
end

local wall0 = shm.C.shm_now()
local next_report = opts.report > 0 and wall0 + opts.report or math.huge
local rss0
-- compiled JIT traces alive (their IR counts in the Lua heap: the soak test tells the JIT's
-- warm-up, bounded by maxtrace, from a leak)
local function traces()
  local ok, util = pcall(require, 'jit.util')
  if not ok then return 0 end
  local n = 0
  for i = 1, 4000 do
    if util.traceinfo(i) then n = n + 1 end
  end
  return n
end

local function report(now)
  collectgarbage('collect')
  local rss = rss_kb()
  rss0 = rss0 or rss
  log('t=%.0fs frames=%d ball=%d bad=%d errors=%d cam_errors=%d rss_kb=%d lua_kb=%.0f traces=%d', now - wall0,
      counts.frames, counts.detected, counts.bad_frames, counts.errors, counts.cam_errors, rss,
      collectgarbage('count'), traces())
end

log('camera %s %dx%d, lut %s', cam_settings.driver, ccfg.width, ccfg.height,
    vcfg.lut or 'from colour boxes')

local participant
local function lockstep_on() return sync.lockstep[0] == 1 end
local next_wake = 0

while true do
  check_blocks()
  if lockstep_on() and cam.driver == 'sim' then
    -- lockstep: at each tick we are due, take the frame the DCM published for it (if any) and
    -- report done. After a frame the next one cannot come for 1/fps, so the DCM is told not to
    -- wait for us until then: ticks without a frame go on without a round trip.
    if not participant then
      participant = lockstep.join()
      next_wake = 0
    end
    local tick = sync.tick[0]
    local done = participant.sync.done_tick[participant.slot]
    if tick ~= done and (tick >= next_wake or participant:due(tick)) then
      local got = step(0)
      local skip = 1
      local period = sensor.period[0]
      if got and period > 0 and cam_settings.fps > 0 then
        skip = math.max(1, math.floor(1 / (cam_settings.fps * period)))
      end
      next_wake = tick + skip
      participant:done(tick, next_wake)
    else
      shm.C.shm_futex_wait(sync.tick, tick, 0.1)
    end
  else
    if participant then participant:leave(); participant = nil end
    step(0.5)
  end
  local now = shm.C.shm_now()
  if now >= next_report then
    report(now)
    next_report = next_report + opts.report
  end
  if (opts.frames and counts.frames >= opts.frames) or (opts.seconds and now - wall0 >= opts.seconds) then
    break
  end
end

if participant then participant:leave() end
report(shm.C.shm_now())
cam:close()
