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
  local path = rawget(vcfg, 'lut')
  if path then
    if path:sub(1, 1) ~= '/' then path = native.root() .. '/' .. path end
    return imageproc.load_lut(path)
  end
  return imageproc.lut_from_colors(vcfg.colors)
end

function M.new(vcfg, ccfg, model)
  local lut, err = M.load_lut(vcfg)
  if not lut then return nil, err end
  local kind = rawget(vcfg.ball, 'kind') or 'orange'
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
    head_joint = rawget(ccfg, 'head_joint') or { 0, 1 },
    pose = { 0, 0, 0, R = { 1, 0, 0, 0, 1, 0, 0, 0, 1 }, height = 0 },
    result = { ball = { detected = false, kind = kind == 'white' and 1 or 0, score = 0 }, goals = { n = 0 },
               robots = { n = 0 } },
    q = {},
  }, Pipeline)
  return self
end

-- Runs the pipeline on a frame. q: joint angles (1-based table in the robot's joint order; the
-- head angles are replaced by the frame's), rpy: {roll, pitch} of the torso at the frame.
-- Returns the detections, or nil and a message for a frame of the wrong size.
function Pipeline:process(frame, q, rpy)
  if frame.width ~= self.width or frame.height ~= self.height then
    return nil, string.format('frame %dx%d, pipeline expects %dx%d', frame.width, frame.height,
                              self.width, self.height)
  end
  local qq = self.q
  for i = 1, #q do qq[i] = q[i] end
  qq[self.head_joint[1] + 1], qq[self.head_joint[2] + 1] = frame.head[0], frame.head[1]
  self.model:camera_pose(qq, rpy, self.pose)
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
