-- The recorder (./run_main --record [DIR]; build/bin/hrp_record): every shm block of the robot into
-- MCAP files, each block when its content changes (so at its own rate), the camera frames JPEG-compressed,
-- the configuration in force as attachments. See Run/recorder/README.md.
return {
  dir = 'logs',                 -- where the files go (relative to the repository root unless absolute)
  file_mb = 256,                -- a file is closed and the next one begun past this size (MB)
  total_mb = 2048,              -- the oldest of the recorder's files in dir are deleted past this total (MB)
  chunk_kb = 512,               -- messages are compressed in chunks of this many KB
  flush_s = 1.0,                -- s of wall time after which an open chunk is written anyway
  zstd_level = 1,               -- chunk compression (0: none)
  queue_mb = 64,                -- messages waiting for the writer; past this new ones are dropped (counted)
  camera = 'jpeg',              -- 'jpeg': camera frames JPEG-compressed; 'raw': the YUYV bytes; 'off'
  jpeg_quality = 85,            -- 0..100
  camera_block = 'camera.image',  -- the block and field holding the raw frame
  camera_field = 'yuyv',
  exclude = { 'bench', 'recorder' },  -- blocks not recorded (the recorder's own statistics, benchmarks)
  history_s = 10,               -- s of every block kept in shared memory for history() in the REPL (0: none)
  -- configuration concerns attached to each file (Config.export of each; absent ones are skipped)
  concerns = { 'robot', 'actuators', 'walk', 'camera', 'vision', 'behavior', 'sim', 'dcm', 'recorder' },
}
