-- The camera of the vision specs that ray-cast their own frames: the OP3's head camera (640 x 480,
-- 43.3 deg vertical field of view) on its kinematic model, the rest of the body at zero and the torso
-- level; the OP3's vision config on the Sim platform.
--   local rc = require('Tests.vision.raycast_camera')
--   rc.W, rc.H, rc.FOVY, rc.cm (project.camera), rc.model, rc.q0 (all joints 0), rc.vcfg, rc.ccfg
--   rc.pose_for(pan, tilt)   the camera pose for the head's angles (negative tilt looks down)
--   rc.render(pose, shade)   a YUYV frame: shade(dx, dy, dz) gives the Y, U, V a pixel's ray meets
--   rc.ball_hit(pose, dx, dy, dz, bx, by, r)   does that ray meet a ball of radius r at (bx, by)?
local ffi = require('ffi')
local kinematics = require('kinematics')
local project = require('Vision.project')

local M = {}
M.W, M.H = 640, 480
M.FOVY = math.rad(43.3)
M.vcfg = require('Config').load('vision', nil, { robot = 'op3', platform = 'Sim' })
M.ccfg = { width = M.W, height = M.H, fovy = M.FOVY, head_joint = { 0, 1 }, exposure_time = 0 }
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

function M.render(pose, shade)
  local buf = ffi.new('uint8_t[?]', M.W * M.H * 2)
  for v = 0, M.H - 1 do
    for u = 0, M.W - 1, 2 do
      local Y, U, V = shade(project.ray(M.cm, pose, u + 0.5, v + 0.5))
      local p = (v * M.W + u) * 2
      buf[p], buf[p + 1], buf[p + 2], buf[p + 3] = Y, U, Y, V
    end
  end
  return buf
end

-- ray-sphere, |c + t d - b|^2 = r^2, in front of the camera
function M.ball_hit(pose, dx, dy, dz, bx, by, r)
  local ground = pose[3] - pose.height
  local ox, oy, oz = pose[1] - bx, pose[2] - by, pose[3] - (ground + r)
  local a = dx * dx + dy * dy + dz * dz
  local b = 2 * (ox * dx + oy * dy + oz * dz)
  local c = ox * ox + oy * oy + oz * oz - r * r
  return b * b - 4 * a * c >= 0 and b < 0
end

return M
