-- The view's latency probe: writes the bench block's t_send (shm_now: CLOCK_MONOTONIC) and bumps k
-- every `period` s for `seconds` s; the page reports the time from each write to its arrival.
--   luajit Tests/view/probe.lua [seconds] [period]
local ffi = require('ffi')
local shm = require('shm')

ffi.cdef [[ int usleep(unsigned usec); ]]
local seconds, period = tonumber(arg[1]) or 10, tonumber(arg[2]) or 0.023
local bench = shm.open('bench')
local C = shm.C
local t_end = C.shm_now() + seconds
local k = bench.k[0]
while C.shm_now() < t_end do
  k = k + 1
  bench:write(function(b)
    b.t_send[0] = C.shm_now()
    b.k[0] = k
  end)
  ffi.C.usleep(period * 1e6)
end
