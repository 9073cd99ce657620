-- A lockstep participant for the replay test: at every tick the Replay DCM serves, checks that dcm.sensor
-- holds Tests/recorder/fake_robot.lua's values for the recorded tick (exactly) and that a new camera frame
-- has that frame's brightness (JPEG: within 4 levels); stops when the DCM has ended. Prints one line:
--   checker: ticks N in_order 0|1 wrong N frames N bad_frames N first_t T last_t T
local ffi = require('ffi')
local shm = require('shm')
local lockstep = require('lockstep')

local sensor = shm.open('dcm.sensor')
local cam = shm.open('camera.image')
local p = lockstep.join()
local sync = p.sync
local word = ffi.cast('volatile uint32_t *', sync.tick)
local C = shm.C

local ticks, wrong, frames, bad_frames, in_order = 0, 0, 0, 0, true
local last_rec, last_frame, first_t, last_t = -1, cam.frame[0], nil, nil
local done, idle_since = 0, C.shm_now()
while true do
  local tick = word[0]
  if tick ~= done and tick > 0 then
    local t = sensor.time[0]
    local rec = math.floor(t / 0.008 + 0.5)
    first_t = first_t or t
    last_t = t
    for j = 0, sensor:count('position') - 1 do
      if sensor.position[j] ~= rec * 1e-3 + j then wrong = wrong + 1 break end
    end
    if sensor.gyro[2] ~= rec / 3 then wrong = wrong + 1 end
    if rec <= last_rec then in_order = false end
    last_rec = rec
    if cam.frame[0] ~= last_frame then
      last_frame = cam.frame[0]
      frames = frames + 1
      local want = 40 + (last_frame * 16) % 160
      local w, h = cam.width[0], cam.height[0]
      for _, px in ipairs({ 0, w * h / 2 + 7, w * h - 1 }) do
        if math.abs(cam.yuyv[2 * px] - want) > 4 then bad_frames = bad_frames + 1 break end
      end
    end
    ticks = ticks + 1
    done = tick
    p:done(tick)
    idle_since = C.shm_now()
  else
    C.shm_futex_wait(word, tick, 0.05)
    -- the DCM stops at the end of the log: no new tick for a while
    if C.shm_now() - idle_since > 1.5 then break end
  end
end
p:leave()
print(string.format('checker: ticks %d in_order %d wrong %d frames %d bad_frames %d first_t %.3f last_t %.3f', ticks,
  in_order and 1 or 0, wrong, frames, bad_frames, first_t or -1, last_t or -1))
