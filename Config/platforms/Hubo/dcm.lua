-- The Hubo platform's DCM settings (Platforms/Hubo/dcm_hubo), the same for every body on Hubo motor
-- boards. The buses and boards (which board drives which joint, gears, encoders, sensor boards)
-- are the body's: Config/robots/<ROBOT>/can.lua.
return {
  start_hardness = 1.0,     -- hardness given to a blank actuator block at start (holds the present pose)
  watchdog = 0.5,           -- s without a new tick_ack from motion before the safe state
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
  safe_hardness = 0.3,      -- safe state: hold the present pose (Hubo boards: position control, see below)
  -- Hubo boards have no per-cycle torque limit (gain override 0x6F is untested in hubo-ach), so a
  -- joint commanded with hardness below `compliant_below` or torque_enable 0 is compliant the way
  -- hubo-ach's compliant mode is: its reference follows the measured position.
  compliant_below = 0.05,
  dead_after = 5,           -- cycles in a row with an answer missing before a board is marked dead
  retry_period = 0.5,       -- s between requests to a dead board (it rejoins when it answers)
  reply_window = 0.8,       -- fraction of the period spent collecting replies (the rest: publish, sleep)
  status_every = 40,        -- cycles between status polls of one motor board (round-robin over boards)
  current_every = 20,       -- cycles between current polls of one motor board (hubo-ach: a twentieth)
  startup_hold = 0.8,       -- s after enable before references are sent (HUBO_STARTUP_SEND_REF_DELAY)
  home_at_start = false,    -- send the homing command (0x11) at start: only on a robot hung in its frame
  home_timeout = 10,        -- s to wait for home state 6 when homing
  enable_at_start = true,   -- FET and controller on (0x0B, 0x0E) for the boards whose channels are homed
  reopen_period = 1.0,      -- s between attempts to reopen a bus whose interface went away
  rt_priority = 40,         -- SCHED_FIFO priority of the DCM (0: normal process); needs the right
}
