-- Replay control from the REPL (PLATFORM=Replay ./run_dcm --log FILE): the `replay` block, served by
-- Platforms/Replay (replay_control.h).
--
--   replay.pause()      -- the clock stops: no tick is served until resume, step or seek
--   replay.resume()
--   replay.step(n)      -- serves exactly n ticks, then holds (pauses first if it was playing)
--   replay.seek(t)      -- serves the tick of log time t (the last at or before it) next; paused: at once
--   replay.speed(x)     -- x times the recorded rate (real-time mode)
--   replay.status()     -- { paused, holding, time, first_time, ticks, speed, steps }
-- Each call returns once the DCM has done it (pause, step and a seek while paused: once the clock is
-- held again) with dcm.sensor.time; errors name a bad argument, or say that no Replay DCM runs.
-- In a lockstep script the script's own hold on the clock is let go while the DCM works, and taken
-- again at the tick it holds (replay.participant, set by Run/repl.lua).
local ffi = require('ffi')
local shm = require('shm')

local M = {}

local CMD = { pause = 1, resume = 2, seek = 3, step = 4, speed = 5 }
local TIMEOUT = 30.0 -- s of wall time a command may take (a long seek decodes its last frame only)

local block = shm.lazy('replay')
local sensor = shm.lazy('dcm.sensor')
M.participant = nil

local function alive()
  local pid = block().pid[0]
  return pid ~= 0 and shm.C.shm_pid_alive(pid) == 1
end

-- Waits (wall time) until cond() holds; an error naming what did not happen.
local function wait_for(cond, what)
  local b = block()
  local deadline = shm.C.shm_now() + TIMEOUT
  local word = ffi.cast('volatile uint32_t *', b.ack)
  while not cond() do
    if not alive() then error('replay: the Replay DCM ended ' .. what, 3) end
    if shm.C.shm_now() > deadline then error(string.format('replay: no answer %s in %.0f s', what, TIMEOUT), 3) end
    shm.C.shm_futex_wait(word, word[0], 0.002)
  end
end

-- A lockstep script lets the clock go while the DCM works, and holds it again where the DCM stopped.
local function release()
  local p = M.participant
  if p then p:done(sensor().tick[0], 0xffffffff) end
end
local function rejoin()
  local p = M.participant
  if p then
    local t = sensor().tick[0]
    p:done(t, t + 1)
    p:settle(t)
  end
end

local function send(name, arg)
  if not alive() then
    error(string.format('replay.%s: no Replay DCM runs for ROBOT_ID %d (PLATFORM=Replay ./run_dcm --log FILE)', name,
      shm.robot_id()), 3)
  end
  local b = block()
  local seq
  b:write(function(x)
    x.command[0] = CMD[name]
    x.arg[0] = arg or 0
    seq = x.seq[0] + 1
    x.seq[0] = seq
  end)
  release()
  wait_for(function() return b.ack[0] == seq end, 'to replay.' .. name)
  if b.status[0] ~= 0 then
    rejoin()
    error(string.format('replay.%s(%s): refused by the DCM (status %d)', name, tostring(arg), b.status[0]), 3)
  end
  return b
end

local function held(what)
  local b = block()
  wait_for(function() return b.holding[0] == 1 end, what)
  rejoin()
  return sensor().time[0]
end

function M.pause()
  send('pause')
  return held('to pause')
end

function M.resume()
  send('resume')
  rejoin()
  return sensor().time[0]
end

function M.step(n)
  n = n or 1
  if type(n) ~= 'number' or n < 1 or n ~= math.floor(n) then
    error('replay.step: a whole number of ticks >= 1 expected, got ' .. tostring(n), 2)
  end
  send('step', n)
  return held('to serve ' .. n .. ' ticks')
end

function M.seek(t)
  if type(t) ~= 'number' or t ~= t or t == math.huge or t == -math.huge then
    error('replay.seek: a log time in s expected, got ' .. tostring(t), 2)
  end
  local b = send('seek', t)
  if b.paused[0] == 1 then return held('to seek') end
  local tick = sensor().tick[0]
  wait_for(function() return sensor().tick[0] ~= tick end, 'to seek')
  rejoin()
  return sensor().time[0]
end

function M.speed(x)
  if type(x) ~= 'number' or x ~= x or x <= 0 or x == math.huge then
    error('replay.speed: a factor > 0 expected, got ' .. tostring(x), 2)
  end
  send('speed', x)
  rejoin()
  return x
end

function M.status()
  local b = block()
  return b:read(function(x)
    return { paused = x.paused[0] == 1, holding = x.holding[0] == 1, time = x.time[0], first_time = x.first_time[0],
      ticks = tonumber(x.ticks[0]), speed = x.speed[0], steps = x.steps[0], running = alive() }
  end)
end

return M
