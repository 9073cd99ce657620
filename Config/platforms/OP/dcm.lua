-- The OP platform's DCM settings (Platforms/OP/dcm_op), the same for every body on Dynamixel buses.
-- The buses (port, baud rate) and their devices (which servo drives which joint, how its counts map
-- to the joint angle, the board with the IMU) are the body's: `buses` and `devices` in
-- Config/robots/<ROBOT>/robot.lua:
--   angle (rad) = direction * (count - zero) * 2*pi / 4096
-- Check each joint on a new robot (./run_repl: Body.set_command) before trusting the walk.
return {
  start_hardness = 1.0,         -- hardness commanded when the DCM starts (it holds the current pose)
  watchdog = 0.5,               -- s without a new tick_ack from motion before the safe state
  -- A writer that stopped (SIGSTOP, a debugger), vanished or loops without acknowledging is as
  -- dangerous as a dead one: after `stall_cycles` DCM cycles without a new tick_ack the DCM looks at
  -- the process (/proc) and goes safe at once. 2, not 1: one late answer is routine on a loaded
  -- machine. A writer that merely was not scheduled burns no CPU and is left to `watchdog` (a busy
  -- machine must not make the robot go limp); one that burnt more than `stall_cpu` s of CPU since
  -- its last tick_ack is looping: a tick of motion takes under 1 ms of CPU (1.4 ms at most measured
  -- over a minute of play: 7000 ticks).  3 ms: twice that, yet a loop that gets a fifth of a CPU trips
  -- within the 2 cycles.
  stall_cycles = 2,
  stall_cpu = 0.003,
  safe_hardness = 0.3,          -- safe state: hold the present pose at this fraction of torque
  dead_after = 5,               -- consecutive missed answers before a servo is marked dead
  retry_period = 0.5,           -- s between retries of a dead servo (one short read)
  timeout_margin = 0.0015,      -- s added to the wire time of expected answers (USB latency)
  latency_timer = 1,            -- ms, FTDI latency timer set through libusb / sysfs
  rt_priority = 20,             -- SCHED_FIFO priority of the DCM (0: normal process); needs the right
}
