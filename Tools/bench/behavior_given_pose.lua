-- DIAGNOSTIC for Tools/bench/score_given_pose.sh only, never for play or tests: the behavior
-- process with its pose filter set ONCE from the sim's truth, at the first step of the playing
-- state (the scenario has placed the robot by then, and leaving the initial state resets the pose
-- to the own-half prior); afterwards it runs on odometry, IMU and vision like the real one. It
-- separates how well the robot plays once localized from how well it localizes on its own.
local behavior = require('Behavior.behavior')
local Sim = require('Sim')

local b = behavior.new()
local step = b.step
local given = false
function b:step()
  step(self)
  if not given and self.game:state() == 'playing' then
    local T = Sim.truth()
    self.world.pose:set_pose(T.x, T.y, T.yaw, 0.05)
    given = true
  end
end
b:run()
