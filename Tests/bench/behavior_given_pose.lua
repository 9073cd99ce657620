-- DIAGNOSTIC for Tests/bench/score_given_pose.sh only, never for play or tests: the behavior
-- process with its pose filter set ONCE from the sim's truth, right after the scenario teleports
-- the robot (as if the robot had been told where it was placed); afterwards it runs on odometry,
-- IMU and vision like the real one. It separates how well the robot plays once localized from how
-- well it localizes on its own.
local behavior = require('Behavior.behavior')
local Sim = require('Sim')

local b = behavior.new()
local step = b.step
local last, given = nil, false
function b:step()
  if not given then
    local T = Sim.truth()
    if last and (T.x - last.x) ^ 2 + (T.y - last.y) ^ 2 > 0.09 then -- the teleport
      self.world.pose:set_pose(T.x, T.y, T.yaw, 0.05)
      given = true
    end
    last = T
  end
  return step(self)
end
b:run()
