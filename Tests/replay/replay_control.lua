-- Replay control from the REPL (Tests/replay/replay_control_test.sh): the Replay DCM started --paused
-- on a recording of Tests/recorder/fake_robot.lua (a tick every 8 ms); pause, step, seek, speed and
-- resume, each checked on dcm.sensor. arg: the log times of the ticks at or before 1.003 s and 0.5 s,
-- of the third tick after the latter, and of the last tick (from the log: the recorder may have missed
-- ticks). Prints TAP.
-- luacheck: globals replay
local ffi = require('ffi')
local shm = require('shm')
ffi.cdef [[ int usleep(unsigned int usec); ]]
local sensor = shm.open('dcm.sensor')
local lockstep = shm.open('sync').lockstep[0] == 1
local want_1003, want_05, want_05_3, want_last = tonumber(arg[1]), tonumber(arg[2]), tonumber(arg[3]),
  tonumber(arg[4])
local n, fails = 0, 0
local base, prefix = tonumber(os.getenv('TAP_BASE') or '0'), os.getenv('TAP_PREFIX') or ''
local function tap(ok, msg)
  n = n + 1
  if not ok then fails = fails + 1 end
  print(string.format('%s %d - %s%s', ok and 'ok' or 'not ok', base + n, prefix, msg))
  io.stdout:flush()
end
local function sleep(s) ffi.C.usleep(math.floor(s * 1e6)) end
local function near(a, b) return math.abs(a - b) < 1e-6 end -- the log's ns stamps against the time field
-- the fake robot's values are functions of its tick: the served sensors belong to the served time
local function consistent()
  local rec = math.floor(sensor.time[0] / 0.008 + 0.5)
  return sensor.position[0] == rec * 1e-3 and sensor.gyro[2] == rec / 3
end

local st = replay.status()
tap(st.running and st.paused, '--paused: the DCM starts paused')
local t0, k0 = replay.pause(), sensor.tick[0]
sleep(0.4)
tap(sensor.time[0] == t0 and sensor.tick[0] == k0,
  string.format('paused, the time stays at %.3f s (0.4 s of wall time)', t0))

local t1 = replay.step(1)
tap(sensor.tick[0] == k0 + 1 and replay.status().ticks == st.ticks + 1 and t1 > t0 and consistent(),
  string.format('step(1) serves exactly one tick (%.3f -> %.3f s)', t0, t1))
local k1, pos = sensor.tick[0], replay.status().ticks
local t5 = replay.step(5)
tap(sensor.tick[0] == k1 + 5 and replay.status().ticks == pos + 5 and consistent(),
  string.format('step(5) serves exactly five ticks (log position %d -> %d, t %.3f s)', pos, replay.status().ticks, t5))
sleep(0.3)
tap(sensor.time[0] == t5 and sensor.tick[0] == k1 + 5, 'and holds the clock after them')

local ts = replay.seek(1.003)
tap(near(ts, want_1003) and consistent(),
  string.format('seek(1.003) serves the tick at %.3f s (the log: %.3f)', ts, want_1003))
sleep(0.3)
tap(sensor.time[0] == ts and replay.status().holding, 'paused after the seek: the time stays')
local tb = replay.seek(0.5)
tap(near(tb, want_05) and consistent(),
  string.format('seek(0.5) back: the tick at %.3f s (the log: %.3f)', tb, want_05))
local ts2 = replay.step(3)
tap(near(ts2, want_05_3) and consistent(), string.format('step(3) goes on from there (%.3f s)', ts2))
local te = replay.seek(1e6)
tap(near(te, want_last), string.format('seek past the end: the last tick (%.3f s)', te))
replay.seek(0)

-- bad arguments are refused naming them, the state is kept
for _, bad in ipairs({ { 'step', 0 }, { 'step', 1.5 }, { 'seek', 0 / 0 }, { 'speed', -1 }, { 'speed', 'x' } }) do
  local ok, err = pcall(replay[bad[1]], bad[2])
  tap(not ok and err:find('replay.' .. bad[1], 1, true) ~= nil, string.format('replay.%s(%s) is refused', bad[1],
    tostring(bad[2])))
end

if not lockstep then
  -- real time: speed x changes the rate the log's ticks are served at (one every period / x)
  replay.speed(4)
  local a, w0 = replay.status().ticks, shm.C.shm_now()
  replay.resume()
  sleep(0.3) -- 1.2 s of the 2 s log at 4x: the log must not run out before pause()
  replay.pause()
  local ticks, wall = replay.status().ticks - a, shm.C.shm_now() - w0
  local rate = ticks * sensor.period[0] / wall
  print(string.format('# speed(4): %d ticks of %.3f s in %.3f s of wall time', ticks, sensor.period[0], wall))
  -- a wall-clock figure on a shared machine: the check is only "faster than real time, never faster
  -- than asked"; the printed rate is the measurement
  tap(rate > 1.5 and rate < 4.5, string.format('speed(4) serves the ticks faster than real time, at most 4x (%.1f)',
    rate))
  local p = sensor.time[0]
  sleep(0.3)
  tap(sensor.time[0] == p, 'pause() stops the clock while playing')
end
-- real time: resumed near the end, the DCM serves the rest and stops (in lockstep a clock nobody waits
-- for is held: the test ends that DCM)
if not lockstep then
  replay.seek(want_last - 0.1)
  replay.resume()
end
print('# tests ' .. n)
if fails > 0 then error(fails .. ' of ' .. n .. ' failed', 0) end
