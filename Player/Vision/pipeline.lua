-- The vision pipeline of one camera: YUYV frame -> labels -> ball and goal posts in the robot frame.
--
--   local pipeline = require('Vision.pipeline')
--   local vp = assert(pipeline.new(Config.load('vision'), Config.load('camera'), kinematics.load()))
--   local det = vp:process(frame, q, rpy)
--   -- frame: a camera frame (yuyv, width, height, head[0..1]); q: joint angles (1-based, robot
--   -- order); rpy: torso {roll, pitch}
--   det.ball.detected, det.ball.x, det.ball.y ...; det.goals.n, det.goals[1].x ...
-- The ball is the colour table's orange one or the white one (candidates and a classifier), as
-- vision.ball.kind says; det.ball.kind is 0 (orange) or 1 (white), det.ball.score the classifier's
-- probability (1 for orange). The field boundary is in vp.bd.top (label rows); det.robots.n, det.robots[i]
-- = { x, y, range, team, u0, v0, u1, v1 } (Vision.detect_robots) when vision.robots.enabled.
-- The result tables are reused from frame to frame.
local imageproc = require('imageproc')
local native = require('native')
local project = require('Vision.project')
local detect = require('Vision.detect')
local detect_white = require('Vision.detect_white')
local detect_robots = require('Vision.detect_robots')
local balldetect = require('balldetect')

local M = {}

local Pipeline = {}
Pipeline.__index = Pipeline

-- The LUT named by the vision config (a path relative to the repo root), or one built from its
-- colour boxes when the config says lut = false. nil, err if the file is missing or corrupt.
function M.load_lut(vcfg)
  local path = vcfg.lut
  if path then
    if path:sub(1, 1) ~= '/' then path = native.root() .. '/' .. path end
    return imageproc.load_lut(path)
  end
  return imageproc.lut_from_colors(vcfg.colors)
end

function M.new(vcfg, ccfg, model)
  local lut, err = M.load_lut(vcfg)
  if not lut then return nil, err end
  local kind = vcfg.ball.kind
  local mlp
  if kind == 'white' then
    mlp, err = balldetect.load_model(vcfg.ball.white.model)
    if not mlp then return nil, err end
  elseif kind ~= 'orange' then
    return nil, string.format("vision.ball.kind is '%s': 'orange' or 'white'", tostring(kind))
  end
  local self = setmetatable({
    kind = kind, mlp = mlp,
    bd = balldetect.new(math.ceil(ccfg.width / vcfg.scale), math.ceil(ccfg.height / vcfg.scale)),
    cfg = vcfg, model = model,
    width = ccfg.width, height = ccfg.height,
    p = imageproc.pipeline({ width = ccfg.width, height = ccfg.height, scale = vcfg.scale,
                             block = vcfg.block, lut = lut }),
    cm = project.from_config(ccfg),
    head_joint = ccfg.head_joint,
    pose = { 0, 0, 0, R = { 1, 0, 0, 0, 1, 0, 0, 0, 1 }, height = 0, blur = { 0, 0 } },
    result = { ball = { detected = false, kind = kind == 'white' and 1 or 0, score = 0 }, goals = { n = 0 },
               robots = { n = 0 } },
    q = {},
    -- the last frame's angles and time (Pipeline:process dates the pose to the exposure's middle)
    exposure = ccfg.exposure_time,
    last = { time = -math.huge, pan = 0, tilt = 0, roll = 0, pitch = 0 },
    rpy = { 0, 0 },
    pose_ends = { { R = {} }, { R = {} } },
  }, Pipeline)
  return self
end

-- The frames' angles are their exposure's end; the image shows the exposure's middle (a smear's
-- centre): each angle goes back by half the exposure at its rate since the last frame (none after a
-- gap of more than 0.1 s: frames missed, or the first one). Sets the head's angles in self.q and
-- self.rpy at `back` exposures before the end (0.5: the middle); returns the rate's factor (0: none).
local MAX_GAP = 0.1
function Pipeline:angles_at(frame, rpy, back)
  local qq, last = self.q, self.last
  local ip, it = self.head_joint[1] + 1, self.head_joint[2] + 1
  local pan, tilt = frame.head[0], frame.head[1]
  local t = frame.time or -math.huge   -- (a test's frame may have no time: no dating)
  local dt = t - last.time
  local k = (self.exposure > 0 and dt > 0 and dt <= MAX_GAP) and back * self.exposure / dt or 0
  qq[ip], qq[it] = pan - k * (pan - last.pan), tilt - k * (tilt - last.tilt)
  self.rpy[1], self.rpy[2] = rpy[1] - k * (rpy[1] - last.roll), rpy[2] - k * (rpy[2] - last.pitch)
  return k
end

-- The pixel offset (du, dv) between where the exposure's start and its end saw the point on the
-- middle pose's optical axis (on the ground, or 5 m away): the smear of a still object.
local blur_ends = { {}, {} }
function Pipeline:blur(frame, rpy, mid)
  local R = mid.R
  local dz = R[7]
  local t = dz < -1e-3 and math.min(5, mid.height / -dz) or 5
  local px, py, pz = mid[1] + t * R[1], mid[2] + t * R[4], mid.height + t * dz
  local ends = blur_ends
  for e = 1, 2 do
    local pose = self.pose_ends[e]
    self:angles_at(frame, rpy, e == 1 and 1 or 0)
    self.model:camera_pose(self.q, self.rpy, pose)
    ends[e][1], ends[e][2] = project.to_image(self.cm, pose, px, py, pz)
  end
  local b = mid.blur
  if ends[1][1] and ends[2][1] then
    b[1], b[2] = ends[1][1] - ends[2][1], ends[1][2] - ends[2][2]
  else
    b[1], b[2] = 0, 0
  end
end

-- Runs the pipeline on a frame. q: joint angles (1-based table in the robot's joint order; the
-- head angles are replaced by the frame's), rpy: {roll, pitch} of the torso at the frame; the head
-- and torso angles dated to the exposure's middle (camera.exposure_time, Pipeline:angles_at), the
-- pose's blur the image's motion during the exposure (Pipeline:blur).
-- Returns the detections, or nil and a message for a frame of the wrong size.
function Pipeline:process(frame, q, rpy)
  if frame.width ~= self.width or frame.height ~= self.height then
    return nil, string.format('frame %dx%d, pipeline expects %dx%d', frame.width, frame.height,
                              self.width, self.height)
  end
  local qq = self.q
  for i = 1, #q do qq[i] = q[i] end
  local pose = self.pose
  local moving = self:angles_at(frame, rpy, 0.5) > 0
  self.model:camera_pose(qq, self.rpy, pose)
  if moving then self:blur(frame, rpy, pose) else pose.blur[1], pose.blur[2] = 0, 0 end
  local last = self.last
  last.time, last.pan, last.tilt = frame.time or -math.huge, frame.head[0], frame.head[1]
  last.roll, last.pitch = rpy[1], rpy[2]
  return self:detect(frame, self.pose)
end

-- The detections of a frame seen from a known camera pose (Vision.project's pose: level frame);
-- process() gives it the pose from the joint angles, a tool the renderer's.
function Pipeline:detect(frame, pose)
  self.p:process(frame.yuyv)
  local res = self.result
  local p, w = self.p, self.cfg.ball.white
  self.bd:boundary(p.labels, p.wa, p.ha, w.green, w.boundary_run)
  self.bd:set_view(self.cm, pose)
  if self.mlp then
    detect_white.ball(self.bd, self.mlp, p, self.cm, pose, frame, self.cfg.ball, res.ball)
  else
    detect.ball(self.p, self.cm, pose, self.cfg.ball, res.ball)
    res.ball.score = res.ball.detected and 1 or 0
  end
  detect.goal_posts(self.p, self.cm, pose, self.cfg.goal, res.goals)
  if self.cfg.robots.enabled then
    detect_robots.find(self.bd, p, self.cm, pose, self.cfg.robots, res.ball, res.robots)
  else
    res.robots.n = 0
  end
  return res
end

return M
