-- The ball seen by a walking robot, scored frame by frame against the sim's truth (run by
-- walk_eye_test.sh: dcm_sim in lockstep with the realistic camera, the motion and vision processes,
-- this script as ./run_repl's lockstep participant).
--   ./run_repl Tests/vision/walk_eye.lua [SECONDS] [SEED]
-- The robot walks a seeded pattern of velocities (forward, sideways, turning, changed every 4 s,
-- turned back toward the centre near the field's edge); the head is commanded every tick: 2/3 of
-- the segments it follows the ball with a sweeping offset (+-0.35 rad pan, +-0.18 rad tilt: the
-- ball across the frame and out of it), 1/3 it sweeps its range as the behavior's scan does (pan
-- +-1.4 rad at 1.4 rad/s, tilt -1.0 .. 0.1 rad); the ball is placed at each segment's start
-- 0.3-4.3 m away at a seeded bearing. Every tick the script keeps the sensors and the truth; for every frame the vision
-- publishes, it takes the truth at the frame's exposure: the camera's pose (the torso's true pose and
-- the joint angles: walk_truth.lua), the ball. A frame is scored when the ball's whole outline lies
-- in the frame and no limb of the robot's own comes near the line of sight (then it may be hidden),
-- 0.3-4 m from the torso; a frame with no part of the ball in it counts for false detections.
-- Besides the vision's own result, the detected pixel is projected to the ground again through
-- other camera poses, to tell where the range error comes from: 'upright' (the joint angles only,
-- the torso taken as upright), 'late' (joints and IMU angles when the vision got the frame: the
-- vision before this test), 'exposure' (joints and IMU angles at the exposure), 'true' (the true
-- camera pose: what the detector's pixel alone costs); 'exp_angle' (the torso angles at the exposure,
-- the legs' angles at the delivery: what the frame carries), 'tick_early' (joints and angles one tick
-- before the exposure's end: the middle of the 10 ms exposure is 5 ms before it).
-- Prints one line per missed or wrong frame (WALK_EYE_VERBOSE=1: every scored frame), the figures
-- and TAP lines; WALK_EYE_GATE names the goals to fail on (recall,false,range,bearing; default all).
-- WALK_EYE_SAVE=file: the figures into a file instead of TAP lines (walk_merge.lua: several runs).
-- WALK_EYE_DRAW=dir: PNGs of the frames (the vision's detection: red circle; the truth's centre:
-- green cross) of misses, false detections, range errors over 8%, bearing errors over 2 deg, frames
-- left out near the own limbs with no detection (up to 30 of each) and every 50th frame scored.
-- luacheck: globals Sim Motion Walk Body wait arg
local shm = require('shm')
local Config = require('Config')
local kinematics = require('kinematics')
local project = require('Vision.project')
local walk_truth = require('Tests.vision.walk_truth')
local stats = require('Tests.vision.walk_stats')

local SECONDS = tonumber(arg[1]) or 60
local SEED = tonumber(arg[2]) or 1
local VERBOSE = os.getenv('WALK_EYE_VERBOSE') == '1'
local DRAW = os.getenv('WALK_EYE_DRAW')

local robot = Config.load('robot')
local ccfg, vcfg, scfg = Config.load('camera'), Config.load('vision'), Config.load('sim')
local model = assert(kinematics.load())
local cm = project.from_config(ccfg)
local wt = walk_truth.new(model, cm, robot)
local R_BALL = scfg.ball.diameter / 2
local R_SEEN = vcfg.ball.diameter / 2        -- the vision projects the centre at its own radius
local head_joint = rawget(ccfg, 'head_joint') or { 0, 1 }
local lim = robot.limits

local sensor, simb, vision = shm.open('dcm.sensor'), shm.open('sim'), shm.open('vision')
local image = DRAW and shm.open('camera.image')
local nj = #robot.joints
local period = Body.period()

local motion = require('Tests.motion.kick_setup').wait_for_motion(wait)
if not motion then print('not ok 1 - the motion process is not running') os.exit(1) end

-- ---- the recent ticks: sensors and truth
local RING = 64
local ring = {}
local function keep()
  local tick = sensor.tick[0]
  local e = ring[tick % RING] or { q = {} }
  e.tick, e.time = tick, sensor.time[0]
  for i = 1, nj do e.q[i] = sensor.position[i - 1] end
  e.roll, e.pitch = sensor.angle[0], sensor.angle[1]
  e.truth = { x = simb.robot[0], y = simb.robot[1], z = simb.robot[2], yaw = simb.robot[3],
              roll = simb.robot[4], pitch = simb.robot[5] }
  e.ball = { simb.ball[0], simb.ball[1], simb.ball[2] }
  e.fallen = simb.fallen[0] ~= 0
  ring[tick % RING] = e
  return e
end
local function at(tick)
  local e = ring[tick % RING]
  return e and e.tick == tick and e or nil
end

-- ---- the pattern
math.randomseed(SEED)
local function rnd(a, b) return a + (b - a) * math.random() end
local function clamp(x, a, b) return math.max(a, math.min(b, x)) end
local function wrap(a) return (a + math.pi) % (2 * math.pi) - math.pi end
local SEG = 4.0
local seg = { t0 = -math.huge }
local field = Config.load('sim').field
local XL, YL = field.length / 2 + field.border - 0.3, field.width / 2 + field.border - 0.3

local function new_segment(now, e)
  local t = e.truth
  seg.t0 = now
  seg.track = math.random() < 2 / 3
  seg.phase = rnd(0, 2 * math.pi)
  -- velocity: mostly forward, some sideways and turning; toward the centre near the edge
  local vx, vy, va = rnd(-0.05, 0.25), rnd(-0.08, 0.08), rnd(-0.6, 0.6)
  if math.abs(t.x) > 2.5 or math.abs(t.y) > 1.8 then
    local back = wrap(math.atan2(-t.y, -t.x) - t.yaw)
    vx, vy, va = 0.1, 0, clamp(back, -0.6, 0.6)
  end
  seg.v = { vx, vy, va }
  Walk.set_velocity(vx, vy, va)
  -- the ball: 0.3-4.3 m away, within the head's reach, on the carpet
  local bx, by
  for _ = 1, 50 do
    local d, b = 0.3 + 4.0 * math.random() ^ 1.3, rnd(-1.5, 1.5)
    bx, by = t.x + d * math.cos(t.yaw + b), t.y + d * math.sin(t.yaw + b)
    if math.abs(bx) < XL and math.abs(by) < YL then break end
  end
  Sim.teleport_ball(bx, by)
end

-- a triangle wave of period 1: -1 .. 1 .. -1
local function tri(x)
  local ph = x - math.floor(x)
  return ph < 0.5 and 4 * ph - 1 or 3 - 4 * ph
end

-- the head's command: following the ball with a sweeping offset, or sweeping its range
local look = {}
local function head_command(now, e)
  local t, s = e.truth, now - seg.t0
  local pan, tilt
  if seg.track then
    local dx, dy = e.ball[1] - t.x, e.ball[2] - t.y
    local c, sn = math.cos(-t.yaw), math.sin(-t.yaw)
    local bx, by = c * dx - sn * dy, sn * dx + c * dy
    -- the torso frame's z of the ground: the torso origin's height
    model:look_at({ bx, by, R_BALL - t.z }, look, e.q)
    pan = look[1] + 0.35 * math.sin(2 * math.pi * s / 3.0 + seg.phase)
    tilt = look[2] + 0.18 * math.sin(2 * math.pi * s / 2.5 + seg.phase)
  else
    -- the behavior's scan (Player/HeadFSM/scan.lua: +-1.4 rad in 2 s, 1.4 rad/s), the tilt across
    -- its rows and beyond (-1.0 .. 0.1 rad in 2.5 s)
    pan = 1.4 * tri(s / 4.0 + seg.phase / (2 * math.pi))
    tilt = -0.45 + 0.55 * tri(s / 5.0 + seg.phase / math.pi)
  end
  pan = clamp(pan, lim.head_pan[1], lim.head_pan[2])
  tilt = clamp(tilt, lim.head_tilt[1], lim.head_tilt[2])
  Body.set_head_command({ pan, tilt })
end

-- ---- scoring
local st = stats.new({ 'vision', 'upright', 'late', 'exposure', 'exp_angle', 'tick_early', 'true' })
st.kind = rawget(vcfg.ball, 'kind') or 'orange'
local pose = { R = {} }
local qq = {}

-- the ground point of pixel (u, v) through the pose from joint angles q (the head's from qh) and
-- the torso angles rpy
local function through(q, qh, rpy, u, v)
  for i = 1, nj do qq[i] = q[i] end
  qq[head_joint[1] + 1], qq[head_joint[2] + 1] = qh[head_joint[1] + 1], qh[head_joint[2] + 1]
  model:camera_pose(qq, rpy, pose)
  return project.to_ground(cm, pose, u, v, R_SEEN)
end

-- The ball's pixel at `back` s before the tick of e (the camera's pose between the ticks kept: the
-- pixels of the two ticks around it, interpolated), or nil.
local function pixel_before(e, back)
  local k = back / period
  local k0 = math.floor(k)
  local a, b = at(e.tick - k0), at(e.tick - k0 - 1)
  if not a or not b then return nil end
  local ua, va = wt:pixel(wt:camera(a.truth, a.q), e.ball[1], e.ball[2], e.ball[3])
  local ub, vb = wt:pixel(wt:camera(b.truth, b.q), e.ball[1], e.ball[2], e.ball[3])
  if not ua or not ub then return nil end
  local s = k - k0
  return ua + s * (ub - ua), va + s * (vb - va)
end
local EXPOSURE = scfg.camera.exposure
-- the vision dates a frame by the camera's exposure time: the sim's must be the camera config's
if math.abs((rawget(ccfg, 'exposure_time') or 0) - EXPOSURE) > 1e-9 then
  print(string.format('not ok 1 - camera.lua exposure_time %s differs from sim.lua camera.exposure %s',
    tostring(rawget(ccfg, 'exposure_time')), tostring(EXPOSURE)))
  os.exit(1)
end

-- the frame still in camera.image (the one the vision just published) as a PNG
local drawn = {}
local function draw(kind, e, det, cam)
  if not DRAW then return end
  drawn[kind] = (drawn[kind] or 0) + 1
  if kind ~= 'sample' and drawn[kind] > 30 or kind == 'sample' and drawn[kind] % 50 ~= 1 then return end
  if image.frame[0] ~= det.frame then return end
  local u, v = wt:pixel(cam, e.ball[1], e.ball[2], e.ball[3])
  local u0, v0 = pixel_before(e, EXPOSURE)
  require('Tests.vision.draw').frame(string.format('%s/%s_s%d_%06d.png', DRAW, kind, SEED, e.tick),
    { width = image.width[0], height = image.height[0], yuyv = image.yuyv }, { p = { scale = 1 } },
    { ball = { detected = det.detected, u = det.u, v = det.v, radius = det.radius } },
    u and { u = u, v = v, radius = 1, u0 = u0, v0 = v0 } or nil)
end

local function score(frame_tick, got_tick, det)
  local e, g = at(frame_tick), at(got_tick)
  if not e or not g then st:count('no truth') return end
  if e.fallen then st:count('fallen') return end
  local t = e.truth
  local cam = wt:camera(t, e.q)
  local view = wt:ball_view(cam, e.ball, R_BALL)
  local dx, dy = e.ball[1] - t.x, e.ball[2] - t.y
  local c, s = math.cos(-t.yaw), math.sin(-t.yaw)
  local tx, ty = c * dx - s * dy, s * dx + c * dy
  local range = math.sqrt(tx * tx + ty * ty)
  if view == 'out' then
    st:empty(det.detected)
    if det.detected then
      draw('false', e, det, cam)
      print(string.format('t %.3f: FALSE detection at %.2f, %.2f (ball %.2f m %+.0f deg, out of view)', e.time,
        det.x, det.y, range, math.deg(math.atan2(ty, tx))))
    end
    return
  end
  if view ~= 'in' or range < 0.3 or range > 4 then st:count('partly in view or out of 0.3-4 m') return end
  if wt:own_body_hides(t, e.q, cam, e.ball, R_BALL) then
    -- not scored: counted with how often the vision found the ball there, to show what is left out
    st:count(det.detected and 'near its own limbs (ball detected)' or 'near its own limbs (not detected)')
    if not det.detected then draw('limbs', e, det, cam) end
    return
  end
  local est = {}
  if det.detected then
    est.vision = { det.x, det.y }
    local u, v = det.u, det.v
    est.upright = { through(g.q, e.q, { 0, 0 }, u, v) }
    est.late = { through(g.q, e.q, { g.roll, g.pitch }, u, v) }
    est.exposure = { through(e.q, e.q, { e.roll, e.pitch }, u, v) }
    est.exp_angle = { through(g.q, e.q, { e.roll, e.pitch }, u, v) }
    local e1 = at(frame_tick - 1)
    if e1 then est.tick_early = { through(e1.q, e1.q, { e1.roll, e1.pitch }, u, v) } end
    est['true'] = { project.to_ground(cm, walk_truth.level_pose(t, cam), u, v, R_SEEN) }
  end
  local ok, note = st:ball(range, tx, ty, det.detected, est)
  if VERBOSE and det.detected then
    -- the detected pixel against the truth's at the exposure's end and its start (the smear's ends)
    local u, v = wt:pixel(cam, e.ball[1], e.ball[2], e.ball[3])
    local u0, v0 = pixel_before(e, EXPOSURE)
    if u and u0 then
      note = note .. string.format('; px det %.1f %.1f end %.1f %.1f start %.1f %.1f r %.1f', det.u, det.v, u, v,
        u0, v0, det.radius)
    end
  end
  if VERBOSE or not ok then
    print(string.format('t %.3f: ball %.2f m %+.1f deg (late %d ticks): %s', e.time, range,
      math.deg(math.atan2(ty, tx)), got_tick - frame_tick, note))
  end
  local big = ok and range <= 3 and math.abs(math.sqrt(det.x ^ 2 + det.y ^ 2) - range) > 0.08 * range
  local berr = ok and math.abs(math.deg(wrap(math.atan2(det.y, det.x) - math.atan2(ty, tx)))) or 0
  draw(big and 'range8' or berr > 2 and 'bearing2' or ok and 'sample' or 'miss', e, det, cam)
end

-- ---- the run
Motion.request('walk')
local t_start = Body.get_time()
local last_frame = vision.frame[0]
local falls, was_fallen = 0, false
local sway = { roll_min = math.huge, roll_max = -math.huge, pitch_min = math.huge, pitch_max = -math.huge, path = 0 }
local last_xy
local det = {}
while Body.get_time() - t_start < SECONDS do
  wait(period)   -- one tick
  local e = keep()
  local now = e.time
  if not e.fallen then
    local t = e.truth
    sway.roll_min, sway.roll_max = math.min(sway.roll_min, t.roll), math.max(sway.roll_max, t.roll)
    sway.pitch_min, sway.pitch_max = math.min(sway.pitch_min, t.pitch), math.max(sway.pitch_max, t.pitch)
    if last_xy then sway.path = sway.path + math.sqrt((t.x - last_xy[1]) ^ 2 + (t.y - last_xy[2]) ^ 2) end
    last_xy = { t.x, t.y }
  end
  if e.fallen then
    if not was_fallen then falls = falls + 1 end
    was_fallen = true
    Sim.teleport_robot(e.truth.x, e.truth.y, e.truth.yaw)
    Motion.request('stand')
  elseif was_fallen then
    was_fallen = false
    Motion.request('walk')
    seg.t0 = -math.huge
  end
  if now - seg.t0 >= SEG then new_segment(now, e) end
  head_command(now, e)
  local f = vision.frame[0]
  if f ~= last_frame then
    last_frame = f
    vision:read(function(b)
      det.detected = b.ball_detected[0] == 1
      det.x, det.y = b.ball_position[0], b.ball_position[1]
      det.u, det.v, det.radius = b.ball_image[0], b.ball_image[1], b.ball_radius[0]
      det.frame = b.frame[0]
      det.time = b.time[0]
    end)
    score(math.floor(det.time / period + 0.5), e.tick, det)
  end
end
Walk.set_velocity(0, 0, 0)
print(string.format('# %.0f s walked (seed %d), %.1f m, %d falls; torso roll %.1f..%.1f deg, pitch %.1f..%.1f deg',
  SECONDS, SEED, sway.path, falls, math.deg(sway.roll_min), math.deg(sway.roll_max), math.deg(sway.pitch_min),
  math.deg(sway.pitch_max)))
print('# frames not scored: ' .. st:skipped())
st:report()
if os.getenv('WALK_EYE_SAVE') then
  st:save(os.getenv('WALK_EYE_SAVE'))   -- the TAP lines come from the runs merged (walk_merge.lua)
else
  st:tap(os.getenv('WALK_EYE_GATE') or 'recall,false,range,bearing', { min_inview = math.floor(SECONDS * 3) })
end
