-- A minimal DCM for tests of the lockstep protocol (the real one is Platforms/Sim):
--   luajit fake_lockstep_dcm.lua NTICKS OUTFILE
-- Publishes NTICKS ticks of period 8 ms in lockstep and writes "tick command[0]" per tick to OUTFILE.
local ffi = require('ffi')
local shm = require('shm')

local n, out_path = tonumber(arg[1]), arg[2]
local C = shm.C
local sensor, actuator, sync = shm.open('dcm.sensor'), shm.open('dcm.actuator'), shm.open('sync')
local pids = ffi.cast('volatile int32_t *', sync.pid)
local done_count = ffi.cast('volatile uint32_t *', sync.done_count)
local out = assert(io.open(out_path, 'w'))
-- the clock starts at 0 whatever an earlier run on this robot id left in the blocks (a script reading a
-- stale tick would ask to be woken past this run's end)
sensor:write(function(s) s.tick[0] = 0; s.time[0] = 0 end)
sync.tick[0] = 0
sync.lockstep[0] = 1

-- hold the clock at 0 until somebody joins, so a script's first commands land on tick 0
local t0 = C.shm_now()
while C.shm_now() - t0 < 10 do
  local any = false
  for i = 0, sync:count('pid') - 1 do if pids[i] > 0 then any = true end end
  if any then break end
  C.shm_futex_wait(done_count, done_count[0], 0.01)
end

for tick = 0, n - 1 do
  sensor:write(function(s) s.tick[0] = tick; s.time[0] = tick * 0.008; s.period[0] = 0.008 end)
  sync.tick[0] = tick
  C.shm_futex_wake(sync.tick)
  while true do
    local seen = done_count[0]
    local waiting = false
    for i = 0, sync:count('pid') - 1 do
      local pid = pids[i]
      if pid > 0 then
        if C.shm_pid_alive(pid) == 0 then C.shm_cas_i32(pids + i, pid, 0)
        elseif sync.wake_tick[i] <= tick and sync.done_tick[i] < tick then waiting = true end
      end
    end
    if not waiting then break end
    C.shm_futex_wait(done_count, seen, 0.05)
  end
  out:write(tick, ' ', actuator.command[0], '\n')
end
sync.lockstep[0] = 0
out:close()
