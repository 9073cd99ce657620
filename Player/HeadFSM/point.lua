-- Head angles that point the camera at a point on the ground given in the robot frame.
local kinematics = require('kinematics')

local M = {}

local model
local out = {}

-- pan, tilt for the ground point (x, y) (robot frame); head: the behavior config's head table
-- (ground_z: the ground in the torso frame; camera_z: the camera above the torso origin).
function M.ground(x, y, head)
  local ground_z = head.ground_z
  if model == nil then
    local ok, m = pcall(kinematics.load)
    model = ok and m or false
  end
  if model then
    local q = model:look_at({ x, y, ground_z }, out)
    return q[1], q[2]
  end
  -- without the kinematic model: pan about z, tilt down (negative) towards the point
  local d = math.sqrt(x * x + y * y)
  return math.atan2(y, x), -math.atan2(-ground_z + head.camera_z, d)
end

return M
