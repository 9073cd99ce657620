-- The camera of the vision specs that ray-cast their own frames: the OP3's head camera (640 x 480,
-- 43.3 deg vertical field of view) on its kinematic model, the rest of the body at zero and the torso
-- level; the OP3's vision config on the Sim platform.
--   local rc = require('Tests.vision.raycast_camera')
--   rc.W, rc.H, rc.FOVY, rc.cm (project.camera), rc.model, rc.q0 (all joints 0), rc.vcfg, rc.ccfg
--   rc.pose_for(pan, tilt)   the camera pose for the head's angles (negative tilt looks down)
local kinematics = require('kinematics')
local project = require('Vision.project')

local M = {}
M.W, M.H = 640, 480
M.FOVY = math.rad(43.3)
M.vcfg = require('Config').load('vision', nil, { robot = 'op3', platform = 'Sim' })
M.ccfg = { width = M.W, height = M.H, fovy = M.FOVY, head_joint = { 0, 1 } }
M.model = assert(kinematics.load({ robot = 'op3' }))
M.cm = project.camera(M.W, M.H, M.FOVY)
M.q0 = {}
for i = 1, #M.model.joints do M.q0[i] = 0 end

function M.pose_for(pan, tilt)
  local q = {}
  for i = 1, #M.q0 do q[i] = M.q0[i] end
  q[1], q[2] = pan, tilt
  return (M.model:camera_pose(q, { 0, 0 }))
end

return M
