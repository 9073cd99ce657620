-- The behavior process: world model, game, body and head state machines, one step every
-- `step_ticks` DCM ticks on the robot's clock (taking part in the sim's lockstep).
--   luajit Player/Behavior/main.lua      (started by ./run_main)
local behavior = require('Behavior.behavior')

local b = behavior.new()
b:run()
