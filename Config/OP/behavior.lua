-- Behavior on the real robots: the simulated robot's parameters (Config/Sim/behavior.lua: same field,
-- same walk speeds and head); team and number from the environment when the team sets them per robot.
local here = debug.getinfo(1, 'S').source:match('^@(.*)/[^/]*$') or 'Config/OP'
local behavior = dofile(here .. '/../Sim/behavior.lua')
behavior.team_number = tonumber(os.getenv('TEAM_NUMBER')) or behavior.team_number
behavior.player_number = tonumber(os.getenv('PLAYER_NUMBER')) or behavior.player_number
return behavior
