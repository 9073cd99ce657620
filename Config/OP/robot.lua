-- The real robot on the OP platform: DARwIn-OP (MX-28, CM-730, protocol 1.0) by default, or
-- ROBOTIS OP3 (XM430, OpenCR, protocol 2.0) with OP_ROBOT=op3 (see dcm.lua). Same 20-joint order
-- and angle convention as Config/Sim/robot.lua: right-hand rule about the joint axes of
-- ../shared/robots/op3_reference.txt, zero = the reference zero pose.
-- the family's joints, groups and limits, found next to this file
local here = debug.getinfo(1, 'S').source:match('^@(.*)/[^/]*$') or 'Config/OP'
local family = dofile(here .. '/../Common/op_family.lua')

local op3 = (os.getenv('OP_ROBOT') or 'darwin') == 'op3'

return {
  name = op3 and 'op3' or 'darwin-op',
  joints = family.joints,     -- Config/Common/op_family.lua
  groups = family.groups,
  limits = family.limits,
  urdf = 'Config/Sim/op3.urdf',
  -- kinematic and mass model: the OP3's is the simulated robot's; the DARwIn-OP's is kinematics.lua
  kinematics = op3 and dofile(here .. '/../Sim/robot.lua').kinematics or dofile(here .. '/kinematics.lua'),
  -- the DCM's control period, s (125 Hz)
  period = 0.008,
}
