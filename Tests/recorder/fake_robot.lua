-- A stand-in robot for the recorder's test: writes dcm.sensor at 125 Hz and camera.image at ~31 Hz for
-- SECONDS (wall clock), every value a known function of the tick, so that the recording can be checked
-- value by value (Tests/recorder/check_mcap.py has the same functions).
--   luajit Tests/recorder/fake_robot.lua SECONDS
local ffi = require('ffi')
local shm = require('shm')

ffi.cdef [[ int usleep(unsigned int usec); ]]

local seconds = tonumber(arg[1]) or 2
local period = 0.008
local sensor = shm.open('dcm.sensor')
local cam = shm.open('camera.image')
local world = shm.open('world')
local w, h = 320, 240

local t0 = shm.C.shm_now()
local tick, frame = 0, 0
while shm.C.shm_now() - t0 < seconds do
  tick = tick + 1
  sensor:write(function(s)
    s.time[0] = tick * period
    s.tick[0] = tick
    s.period[0] = period
    for j = 0, sensor:count('position') - 1 do
      s.position[j] = tick * 1e-3 + j
      s.velocity[j] = -j / 7
    end
    s.gyro[2] = tick / 3
    s.button[1] = tick % 2
  end)
  if tick % 4 == 0 then
    frame = frame + 1
    cam:write(function(c)
      c.width[0], c.height[0], c.frame[0], c.time[0] = w, h, frame, tick * period
      -- a grey frame whose brightness follows the frame number: Y, U, V
      local y = 40 + (frame * 16) % 160
      for i = 0, w * h - 1 do
        c.yuyv[2 * i] = y
        c.yuyv[2 * i + 1] = 128
      end
    end)
  end
  if tick % 16 == 0 then
    world:write(function(x) x.pose[0], x.pose[1], x.pose[2] = tick * 0.01, -tick * 0.02, 0.5 end)
  end
  local wait = t0 + tick * period - shm.C.shm_now()
  if wait > 0 then ffi.C.usleep(math.floor(wait * 1e6)) end
end
io.stdout:write(string.format('fake_robot: %d ticks, %d frames\n', tick, frame))
