-- Walk parameters of the real robots on the OP platform (Player/Motion/walk.lua).
-- Starting point: the simulated OP3's parameters (Config/Sim/walk.lua: same servos, same joint
-- convention). OP_ROBOT=op3 takes them as they are; the DARwIn-OP (default, see robot.lua) has
-- shorter legs (hip 0.2195 m above the soles against the OP3's 0.25) and narrower hips (0.037 m),
-- so its posture and step limits are scaled to its geometry below. Not yet tuned on hardware:
-- expect to adjust the gains and trims (Walk.set from ./run_repl while the robot walks).
local here = debug.getinfo(1, 'S').source:match('^@(.*)/[^/]*$') or 'Config/OP'
local walk = dofile(here .. '/../Sim/walk.lua')

if (os.getenv('OP_ROBOT') or 'darwin') ~= 'op3' then
  -- the torso origin (hip yaw height, Config/OP/kinematics.lua) is 0.248 m up with straight legs;
  -- bent by about the same fraction of the leg as the OP3's stance
  walk.bodyHeight = 0.225
  walk.tZmp = 0.155                 -- sqrt(0.235 m COM height / g)
  walk.footY = 0.037                -- the hip offset: legs straight down in the stance
  walk.stepHeight = 0.03
  walk.stepLimitX = { -0.05, 0.09 }
  walk.stepLimitY = { 0.074, 0.14 }
  walk.velLimitX = { -0.12, 0.30 }
  walk.velLimitY = { -0.12, 0.12 }
end

return walk
