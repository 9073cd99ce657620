-- The OP DCM's bus: which servos, how their counts map to joint angles, which board.
-- Chosen by OP_ROBOT (default 'darwin') or `./run_dcm --robot op3`. Read by Platforms/OP/dcm_op.
-- Every per-joint array is in the joint order of robot.lua.
--   angle (rad) = direction * (count - zero) * 2*pi / 4096
-- zero: the count at the joint's zero pose (2048 = servo centre) plus the robot's calibration.
-- direction: +1 where the servo turns positively about the joint axis of op3_reference.txt. The
-- OP3's URDF axes are the servos' own (all +1); DARwIn-OP shares the layout. Check each joint on
-- a new robot (./run_repl: Body.set_command) before trusting the walk.

-- Servo ids in joint order (head_pan, head_tilt, l_sho_pitch ... r_el): ROBOTIS numbering,
-- odd = right side, even = left side, 19/20 = head; the same on DARwIn-OP and OP3.
local IDS = { 19, 20, 2, 4, 6, 8, 10, 12, 14, 16, 18, 7, 9, 11, 13, 15, 17, 1, 3, 5 }

local function rep(v) local t = {} for i = 1, 20 do t[i] = v end return t end

local robots = {
  darwin = {
    protocol = 1,             -- Dynamixel protocol 1.0
    port = '/dev/ttyUSB0',    -- the CM-730's FTDI; --port overrides
    baud = 1000000,
    servo = 'MX-28',          -- control table and units (Platforms/OP/dcm_op.c knows MX-28, XM430)
    board = 'CM-730',         -- sub-controller with gyro, accelerometer, buttons
    board_id = 200,
    ids = IDS,
    direction = rep(1),
    zero = rep(2048),
  },
  op3 = {
    protocol = 2,
    port = '/dev/ttyUSB0',    -- the OpenCR (USB CDC); --port overrides
    baud = 1000000,
    servo = 'XM430',
    board = 'OpenCR',
    board_id = 200,
    ids = IDS,
    direction = rep(1),
    zero = rep(2048),
  },
}

local which = os.getenv('OP_ROBOT') or 'darwin'
local r = robots[which]
if not r then error("Config/OP/dcm.lua: unknown OP_ROBOT '" .. which .. "' (darwin or op3)") end

-- common to both
r.name = which
r.start_hardness = 1.0        -- hardness commanded when the DCM starts (it holds the current pose)
r.watchdog = 0.5              -- s without a new tick_ack from motion before the safe state
r.safe_hardness = 0.3         -- safe state: hold the present pose at this fraction of torque
r.dead_after = 5              -- consecutive missed answers before a servo is marked dead
r.retry_period = 0.5          -- s between retries of a dead servo (one short read)
r.timeout_margin = 0.0015     -- s added to the wire time of expected answers (USB latency)
r.latency_timer = 1           -- ms, FTDI latency timer set through libusb / sysfs
r.rt_priority = 20            -- SCHED_FIFO priority of the DCM (0: normal process); needs the right
r.gyro_sign = { 1, 1, 1 }     -- board axes to torso axes (x forward, y left, z up)
r.accel_sign = { 1, 1, 1 }
return r
