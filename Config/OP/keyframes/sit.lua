-- The OP platform's sit: the simulated OP3's frames (same joint order and convention, Config/Sim/keyframes),
-- not yet tried on a real robot.
local here = debug.getinfo(1, 'S').source:match('^@(.*)/[^/]*$') or 'Config/OP/keyframes'
return dofile(here .. '/../../Sim/keyframes/sit.lua')
