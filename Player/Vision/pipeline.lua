-- The vision pipeline of one camera: YUYV frame -> labels -> ball and goal posts in the robot frame.
--
--   local pipeline = require('Vision.pipeline')
--   local vp = assert(pipeline.new(Config.load('vision'), Config.load('camera'), kinematics.load()))
--   local det = vp:process(frame, q, rpy)
--   -- frame: a camera frame (yuyv, width, height, head[0..1]); q: joint angles (1-based, robot
--   -- order); rpy: torso {roll, pitch}
--   det.ball.detected, det.ball.x, det.ball.y ...; det.goals.n, det.goals[1].x ...;
--   det.robots.n, det.robots[1].x, .team ... (Vision.robots)
-- The result tables are reused from frame to frame.
local imageproc = require('imageproc')
local native = require('native')
local project = require('Vision.project')
local detect = require('Vision.detect')
local robots = require('Vision.robots')

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
  local self = setmetatable({
    cfg = vcfg, model = model,
    width = ccfg.width, height = ccfg.height,
    p = imageproc.pipeline({ width = ccfg.width, height = ccfg.height, scale = vcfg.scale,
                             block = vcfg.block, lut = lut }),
    cm = project.camera(ccfg.width, ccfg.height, ccfg.fovy),
    head_joint = rawget(ccfg, 'head_joint') or { 0, 1 },
    pose = { 0, 0, 0, R = { 1, 0, 0, 0, 1, 0, 0, 0, 1 }, height = 0 },
    result = { ball = { detected = false }, goals = { n = 0 }, robots = { n = 0 } },
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
  self.p:process(frame.yuyv)
  local res = self.result
  detect.ball(self.p, self.cm, self.pose, self.cfg.ball, res.ball)
  detect.goal_posts(self.p, self.cm, self.pose, self.cfg.goal, res.goals)
  robots.detect(self.p, self.cm, self.pose, self.cfg.robots, res.robots)
  return res
end

return M
