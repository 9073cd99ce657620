-- The Replay platform's DCM (Platforms/Replay/dcm_replay): a recording (./run_main --record) served
-- back into the shm blocks, so vision, world model and behavior run unchanged on recorded data:
--   PLATFORM=Replay ./run_dcm --log FILE [--speed X] [--lockstep]
-- The robot's commands go nowhere: its body is the recording.
return {
  speed = 1.0,                  -- 1: the recorded robot's own rate; 2: twice as fast (--speed)
  -- the blocks served from the log (dcm.sensor is required; a block the log lacks is left alone). The
  -- processes under test write the others (vision, world, game). The motion process does not run under
  -- Replay (./run_main leaves it out): its block -- odometry, state, falls -- is the recording's, which
  -- the world model reads.
  serve = { 'dcm.sensor', 'camera.image', 'sim', 'motion' },
  -- fields of served blocks that the processes under test write (the behavior's requests, walk
  -- velocity, head angles and kicks out of the walk into the motion block; a REPL's parameter requests
  -- and taken joints):
  -- left to them, so that the behavior reads back what it wrote itself, as it did when recorded
  leave = { 'motion.request', 'motion.request_seq', 'motion.request_arg', 'motion.velocity', 'motion.head_command',
    'motion.param_seq', 'motion.param_name', 'motion.param_count', 'motion.param_value',
    'motion.kick_request', 'motion.kick_ball', 'motion.kick_seq', 'motion.taken', 'motion.taken_command' },
  camera_field = 'yuyv',        -- the raw image field the recorder compresses (recorder.camera_field)
  start_hardness = 0.0,         -- nothing to drive
  watchdog = 0,                 -- no servos to protect
  stall_cycles = 0,             -- no servos to protect
  stall_cpu = 0,
  safe_hardness = 0.0,
}
