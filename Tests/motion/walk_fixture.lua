-- What the walk specs share: the default body, its walk config, its kinematic model and tick, and
-- a deep copy of the config a spec may change without touching the one other specs read.
local Config = require('Config')
local kin = require('kinematics')

local M = {}
M.robot = Config.load('robot')
M.params = Config.load('walk')
M.model = kin.load()
M.dt = M.robot.period

local function copy(t)
  local c = {}
  for k, v in pairs(t) do c[k] = type(v) == 'table' and copy(v) or v end
  return c
end
M.copy = copy

return M
