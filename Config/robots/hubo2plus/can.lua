-- The Hubo2+'s CAN buses and boards (the `can` concern, read by Platforms/Hubo/dcm_hubo and
-- Platforms/Hubo/emulator/hubo_emulator through Lib/Config.lua). Facts from shared/robots/hubo_can.md (2.1, 2.3, 6)
-- and hubo_reference.txt (ACTUATORS): hubo-ach's tables/huboplus.joint.table and sensor table,
-- HuboCan's devices/Hubo2Plus/*.dd.
--
-- buses: hubo-ach's bus 0 ("lower", legs and waist) is bus 1 here, its bus 1 ("upper") bus 2.
-- boards: one row per board; motor boards ('jmc': 1- or 2-channel) list their channels:
--   channel   0-based motor index on the board (motNo)
--   joint     the body's joint (robot.lua `joints`), by name
--   drive, driven, harmonic, encoder   belt/pulley teeth, harmonic-drive ratio, counts per motor turn:
--             angle (rad) = direction * (counts - zero) * drive / (driven * harmonic * encoder) * 2 pi
--   direction +1 / -1: hubo-ach keeps every joint's sign in the boards (dir = 1 everywhere)
--   zero      counts at the joint's zero (0: the homed position is the encoder's zero)
--   max_speed rad/s: no reference step larger than max_speed * period is ever sent (HuboCan's
--             software limit v_max, devices/Hubo2Plus/*.dd, hubo_reference.txt LIMITS)
--   torque_constant, max_current   current mode (H_SET_CTRL_MODE 1, the joint's torque mode): the
--             motor's torque constant (N*m/A) and the largest current reference sent (A); a channel
--             without them has no torque mode. Joint torque = current * torque_constant * the gears'
--             ratio (driven * harmonic / drive); the torque limit is the joint's drive's (robot.lua
--             `actuator`, Config/common/actuators.lua), never more than max_current gives.
-- Sensor boards give `sensor` (their number $; command frames address 0x2F + $) and `mount` (the
-- slot of dcm.sensor.ft: left_foot, right_foot, left_hand, right_hand), `signs` for Mx, My, Fz.
-- `active = false`: on the bus but not driven (the DCM leaves it alone and reports its joints dead).
--
-- Left out: EJMC2's channel 0 is the neck yaw NKY, which the public model (and so the body) lacks;
-- the finger boards EJMC4/EJMC5 (5 fingers each, open-loop PWM; not in the body).
--
-- The motors' torque constant is in no public source (hubo_reference.txt, ACTUATORS: motor type,
-- power and torque constant not found). Chosen, and why: brushed DC motors of the 10-200 W class
-- wound for 24-48 V have torque constants of roughly 0.01 to 0.06 N*m/A (catalogue figures of that
-- class, not of the Hubo's motors). The highest, 0.06, is taken: the current sent for a torque is
-- torque / (0.06 * ratio), so if the real motor's constant is lower the joint gets less torque than
-- asked, never more (a weak arm sags; a strong one would be flung); the gears' efficiency (a harmonic
-- drive's 70-85 %) is left out for the same reason. max_current 10 A: the boards' current reply
-- reads at most 10.23 A (hubo_can.md 5.3), so nothing is commanded that the board cannot report back;
-- with the drives' torques (actuators.lua) the largest current asked is 95 / (0.06 * 160) = 9.9 A
-- at a knee, 4.2 A at an elbow, 1.5 A at a wrist.
local KT, IMAX = 0.06, 10
local function leg(joint, drive, driven, harmonic, max_speed)
  return { joint = joint, drive = drive, driven = driven, harmonic = harmonic, encoder = 4000, direction = 1,
           zero = 0, max_speed = max_speed or 7, torque_constant = KT, max_current = IMAX }
end
local function arm(joint, drive, driven)
  return { joint = joint, drive = drive or 1, driven = driven or 1, harmonic = 100, encoder = 4000, direction = 1,
           zero = 0, max_speed = 6, torque_constant = KT, max_current = IMAX }
end
local function ch(n, t) t.channel = n return t end

return {
  bitrate = 1000000,                 -- bit/s on every bus (hubo_can.md 1)
  buses = {
    { name = 'lower', interface = 'can0' },
    { name = 'upper', interface = 'can1' },
  },
  boards = {
    -- bus 1 (lower): legs and waist
    { board = 'JMC0', bus = 1, number = 0x00, kind = 'jmc',
      channels = { ch(0, leg('RHY', 10, 25, 100)), ch(1, leg('RHR', 324, 1024, 160)) } },
    { board = 'JMC1', bus = 1, number = 0x01, kind = 'jmc', channels = { ch(0, leg('RHP', 16, 20, 160)) } },
    { board = 'JMC2', bus = 1, number = 0x02, kind = 'jmc', channels = { ch(0, leg('RKN', 16, 16, 160)) } },
    { board = 'JMC3', bus = 1, number = 0x03, kind = 'jmc',
      channels = { ch(0, leg('RAP', 10, 25, 100)), ch(1, leg('RAR', 324, 1024, 100)) } },
    { board = 'JMC4', bus = 1, number = 0x04, kind = 'jmc',
      channels = { ch(0, leg('LHY', 10, 25, 100)), ch(1, leg('LHR', 324, 1024, 160)) } },
    { board = 'JMC5', bus = 1, number = 0x05, kind = 'jmc', channels = { ch(0, leg('LHP', 16, 20, 160)) } },
    { board = 'JMC6', bus = 1, number = 0x06, kind = 'jmc', channels = { ch(0, leg('LKN', 16, 16, 160)) } },
    { board = 'JMC7', bus = 1, number = 0x07, kind = 'jmc',
      channels = { ch(0, leg('LAP', 10, 25, 100)), ch(1, leg('LAR', 324, 1024, 100)) } },
    { board = 'EJMC3', bus = 1, number = 0x23, kind = 'jmc', channels = { ch(0, leg('WST', 10, 25, 100, 6)) } },
    { board = 'RFFT', bus = 1, sensor = 1, kind = 'ft_tilt', mount = 'right_foot', signs = { 1, 1, 1 } },
    { board = 'LFFT', bus = 1, sensor = 2, kind = 'ft_tilt', mount = 'left_foot', signs = { 1, 1, 1 } },
    { board = 'IMU0', bus = 1, sensor = 3, kind = 'imu' },
    -- bus 2 (upper): arms, wrists, neck, power
    { board = 'JMC8', bus = 2, number = 0x08, kind = 'jmc',
      channels = { ch(0, arm('RSP', 11, 16)), ch(1, arm('RSR')) } },
    { board = 'JMC9', bus = 2, number = 0x09, kind = 'jmc',
      channels = { ch(0, arm('RSY')), ch(1, arm('REB', 20, 20)) } },
    { board = 'JMC10', bus = 2, number = 0x0A, kind = 'jmc',
      channels = { ch(0, arm('LSP', 11, 16)), ch(1, arm('LSR')) } },
    { board = 'JMC11', bus = 2, number = 0x0B, kind = 'jmc',
      channels = { ch(0, arm('LSY')), ch(1, arm('LEB', 20, 20)) } },
    { board = 'EJMC0', bus = 2, number = 0x20, kind = 'jmc', channels = { ch(0, arm('RWY')), ch(1, arm('RWP')) } },
    { board = 'EJMC1', bus = 2, number = 0x21, kind = 'jmc', channels = { ch(0, arm('LWY')), ch(1, arm('LWP')) } },
    -- the 3-channel neck board: reference and encoder formats of the Hubo2+ neck are unknown
    -- (hubo_can.md 4.1, 5.1, 11) and hubo-ach marks it inactive: listed, not driven
    { board = 'EJMC2', bus = 2, number = 0x22, kind = 'jmc3', active = false, channels = {
      { channel = 1, joint = 'NK1', drive = 1, driven = 1, harmonic = 100, encoder = 128, direction = 1, zero = 0,
        max_speed = 6 },
      { channel = 2, joint = 'NK2', drive = 1, driven = 1, harmonic = 100, encoder = 128, direction = 1, zero = 0,
        max_speed = 6 } } },
    { board = 'RHFT', bus = 2, sensor = 6, kind = 'ft', mount = 'right_hand', signs = { 1, 1, 1 } },
    { board = 'LHFT', bus = 2, sensor = 7, kind = 'ft', mount = 'left_hand', signs = { 1, 1, 1 } },
    { board = 'power', bus = 2, number = 0x0E, kind = 'power' },
  },
}
