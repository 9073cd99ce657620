-- A stand-in body for the Hubo CAN tests while Config/robots/hubo2plus/robot.lua is not in the
-- tree (it comes with the simulated Hubo2+): the 27 joints by their hubo-ach names, the HuboCan
-- software limits (hubo_reference.txt LIMITS), the 200 Hz period. The tests copy Config into a
-- temporary tree and put this file there as the body's robot.lua only when the real one is missing.
local joints = { 'WST', 'NK1', 'NK2',
  'RHY', 'RHR', 'RHP', 'RKN', 'RAP', 'RAR', 'LHY', 'LHR', 'LHP', 'LKN', 'LAP', 'LAR',
  'RSP', 'RSR', 'RSY', 'REB', 'RWY', 'RWP', 'LSP', 'LSR', 'LSY', 'LEB', 'LWY', 'LWP' }
return {
  name = 'hubo2plus',
  period = 0.005,
  joints = joints,
  groups = {
    head = { 'NK1', 'NK2' }, waist = { 'WST' },
    lleg = { 'LHY', 'LHR', 'LHP', 'LKN', 'LAP', 'LAR' }, rleg = { 'RHY', 'RHR', 'RHP', 'RKN', 'RAP', 'RAR' },
    larm = { 'LSP', 'LSR', 'LSY', 'LEB', 'LWY', 'LWP' }, rarm = { 'RSP', 'RSR', 'RSY', 'REB', 'RWY', 'RWP' },
  },
  limits = {
    WST = { -3.14, 3.14 }, NK1 = { -0.5236, 0.5236 }, NK2 = { -0.5236, 0.5236 },
    RHY = { -1.92, 1.92 }, RHR = { -0.52, 0.52 }, RHP = { -1.57, 1.57 }, RKN = { 0, 2.609 },
    RAP = { -1.70, 1.70 }, RAR = { -1.57, 1.57 },
    LHY = { -1.92, 1.92 }, LHR = { -0.52, 0.52 }, LHP = { -1.57, 1.57 }, LKN = { 0, 2.609 },
    LAP = { -1.70, 1.70 }, LAR = { -1.57, 1.57 },
    RSP = { -3.14, 3.14 }, RSR = { -3.14, 0.262 }, RSY = { -3.14, 2.0 }, REB = { -2.65, 0 },
    RWY = { -3.14, 3.14 }, RWP = { -1.57, 0.35 },
    LSP = { -3.14, 3.14 }, LSR = { -0.262, 3.14 }, LSY = { -2.0, 3.14 }, LEB = { -2.65, 0 },
    LWY = { -3.14, 3.14 }, LWP = { -1.57, 0.35 },
  },
}
