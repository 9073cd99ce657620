-- Faults while playing (run by Tests/fault/faults_test.sh beside `./run_main --sim`, real time):
--   luajit Tests/fault/faults.lua MAIN_PID SEED [FAULT ...]
-- Waits until the robot walks, then, at a random moment (0.5-3 s after it walks again), injects each
-- fault (in a random order for SEED) into run_main's children and prints one line per fault:
--   fault kill:motion safe_ms=9.8 safe_cycles=1 walking_after=3.10 wall=2.95 others=ok fallen=0 pids=...
-- safe_ms: wall time from the fault to the DCM's safe state (dcm.stats.watchdog_trips), as this poller
-- sees it (every 2 ms); safe_cycles: the DCM's ticks from the fault to the trip as seen here; dcm_lag: the
-- DCM's own count of its cycles from motion's last answer to the trip (dcm.stats.watchdog_lag); starve adds max_lag
-- (the most DCM ticks motion's answer was behind) and trip_lag (how far behind at a trip); walking_after:
-- robot time until the robot walks again; others: the processes not hit kept working meanwhile.
-- Faults: kill:motion kill:vision kill:behavior stop:motion stop:vision stop:behavior busy:motion
-- starve:motion kill:dcm. busy: motion loops for ever ($HRP_FAULT_BUSY names the file that makes it:
-- Player/Motion/main.lua). starve: motion (at nice 19) shares one CPU with 3 busy processes for 3 s
-- (runnable, not running: late answers, which must not trip the stall check, only the timeout if one
-- is 0.5 s late).
-- Reads only shm (an observer, not a lockstep participant) and /proc; the wall clock only for figures.
local ffi = require('ffi')
local shm = require('shm')
ffi.cdef [[ int kill(int pid, int sig); int usleep(unsigned int usec); ]]
local BUSY_FILE = os.getenv('HRP_FAULT_BUSY')
local SIGKILL, SIGSTOP = 9, 19

local main_pid, seed = tonumber(arg[1]), tonumber(arg[2] or 1)
assert(main_pid, 'usage: faults.lua MAIN_PID SEED [FAULT ...]')
local faults = { select(3, ...) }
if #faults == 0 then
  faults = { 'kill:motion', 'kill:vision', 'kill:behavior', 'stop:motion', 'stop:vision', 'stop:behavior',
    'busy:motion', 'starve:motion', 'kill:dcm' }
end
math.randomseed(seed)
for i = #faults, 2, -1 do
  local j = math.random(i)
  faults[i], faults[j] = faults[j], faults[i]
end

local sensor, stats, actuator = shm.open('dcm.sensor'), shm.open('dcm.stats'), shm.open('dcm.actuator')
local motion, vision, game, sim = shm.open('motion'), shm.open('vision'), shm.open('game'), shm.open('sim')
local now = shm.C.shm_now
local function sleep(s) ffi.C.usleep(math.floor(s * 1e6)) end

-- poll cond every 2 ms for at most `limit` wall seconds; the wall time it took, or nil
local function wait_for(cond, limit)
  local t0 = now()
  while now() - t0 < limit do
    if cond() then return now() - t0 end
    sleep(0.002)
  end
  return nil
end

local SCRIPTS = { motion = 'Player/Motion/main.lua', vision = 'Player/Vision/main.lua',
  behavior = 'Player/Behavior/main.lua', dcm = 'dcm_sim' }
-- the pid of run_main's child NAME (from /proc), or nil
local function child(name)
  local f = io.open(string.format('/proc/%d/task/%d/children', main_pid, main_pid))
  if not f then return nil end
  local list = f:read('*a')
  f:close()
  for pid in list:gmatch('%d+') do
    local c = io.open('/proc/' .. pid .. '/cmdline')
    local cmd = c and c:read('*a') or ''
    if c then c:close() end
    if cmd:find(SCRIPTS[name], 1, true) then return tonumber(pid) end
  end
  return nil
end
local function pids()
  return string.format('%s/%s/%s', child('motion'), child('vision'), child('behavior'))
end

local function walking() return motion.walking[0] == 1 and game.state[0] == 3 end

-- a progress counter per process, to see who keeps working while another is down
local PROGRESS = {
  motion = function() return motion.tick[0] end,
  vision = function() return vision.frame[0] end,
  behavior = function() return game.time[0] end,
  dcm = function() return sensor.tick[0] end,
}
local function snapshot()
  local s = {}
  for k, f in pairs(PROGRESS) do s[k] = f() end
  return s
end

local function run_fault(fault)
  local kind, name = fault:match('^(%a+):(%a+)$')
  local pid = child(name)
  if not pid then print('fault ' .. fault .. ' error=no_process') return end
  local before_pids = pids()
  local t_robot, t_wall, tick_fault = sensor.time[0], now(), sensor.tick[0]
  local trips = stats.watchdog_trips[0]
  local fell = 0
  local max_lag, trip_lag = 0, nil
  local others_before = snapshot()
  if kind == 'kill' then ffi.C.kill(pid, SIGKILL)
  elseif kind == 'stop' then ffi.C.kill(pid, SIGSTOP)
  elseif kind == 'busy' then
    assert(BUSY_FILE, 'busy: needs $HRP_FAULT_BUSY (as in faults_test.sh)')
    io.open(BUSY_FILE, 'w'):close()
  elseif kind == 'starve' then
    -- motion at nice 19 and 3 busy processes on CPU 0 for 3 s: runnable, rarely running, late (nice 0
    -- again needs CAP_SYS_NICE: without it motion stays at 19, only later still)
    os.execute(string.format('taskset -a -p -c 0 %d >/dev/null; renice -n 19 -p %d >/dev/null', pid, pid))
    os.execute("for i in 1 2 3; do taskset -c 0 timeout 3 sh -c 'while :; do :; done' & done")
    -- how late motion got (DCM ticks since its last answer), and how late it was at a trip
    local t0 = now()
    while now() - t0 < 3.2 do
      if sim.fallen[0] ~= 0 then fell = 1 end
      local lag = sensor.tick[0] - actuator.tick_ack[0]
      if lag > max_lag then max_lag = lag end
      if not trip_lag and stats.watchdog_trips[0] ~= trips then trip_lag = lag end
      sleep(0.002)
    end
    os.execute(string.format('taskset -a -p -c 0-1023 %d >/dev/null 2>&1 || taskset -a -p ffffffff %d >/dev/null; '
      .. 'renice -n 0 -p %d >/dev/null 2>&1', pid, pid, pid))
  end
  -- the DCM's safe state (motion faults only: the others leave motion answering), in wall time as
  -- seen from here and in the DCM's ticks
  -- (busy: from motion's last answer, the moment it starts looping, not from the file's creation,
  -- which it sees only at the end of its next tick)
  local trip_tick, dcm_lag, last_ack, last_ack_t = nil, nil, actuator.tick_ack[0], now()
  local safe = wait_for(function()
    if actuator.tick_ack[0] ~= last_ack then last_ack, last_ack_t = actuator.tick_ack[0], now() end
    if stats.watchdog_trips[0] == trips then return false end
    trip_tick, dcm_lag = sensor.tick[0], stats.watchdog_lag[0]
    return true
  end, name == 'motion' and 3 or 0.6)
  if safe and kind == 'busy' then
    safe = safe - (last_ack_t - t_wall)
    tick_fault = last_ack
  end
  -- the others keep working while NAME is down (real time: nobody waits on anybody)
  -- (with the DCM down every clock stands: nothing to compare)
  -- (each gets 2 s of wall time to show progress: a loaded machine may run the sim slower than real time)
  local others = name == 'dcm' and 'n/a' or 'ok'
  if name ~= 'dcm' then
    for k, f in pairs(PROGRESS) do
      if k ~= name and not wait_for(function() return f() ~= others_before[k] end, 2.0) then others = 'held:' .. k end
    end
  end
  -- recovery: a new process (a hung one is killed by run_main's hang watch), then walking again
  -- (walking: on ticks motion handled after the fault, of a DCM that is not the killed one)
  local tick0 = motion.tick[0]
  local back = wait_for(function()
    if sim.fallen[0] ~= 0 then fell = 1 end
    local p = child(name)
    local renewed = kind == 'starve' or (p and p ~= pid)
    local fresh = motion.tick[0] > tick0 + 10 and (name ~= 'dcm' or sensor.dcm_pid[0] ~= pid)
    return renewed and fresh and walking()
  end, 40)
  print(string.format('fault %s pid=%d safe_ms=%s safe_cycles=%s dcm_lag=%s%s walking_after=%s wall=%s '
    .. 'others=%s fallen=%d trips=%d pids=%s->%s', fault, pid, safe and string.format('%.1f', safe * 1e3) or 'none',
    trip_tick and tostring(trip_tick - tick_fault) or 'none', dcm_lag and tostring(dcm_lag) or 'none',
    kind == 'starve' and string.format(' max_lag=%d trip_lag=%s', max_lag, trip_lag or 'none') or '',
    back and string.format('%.2f', sensor.time[0] - t_robot) or 'never',
    back and string.format('%.2f', now() - t_wall) or 'never', others, fell,
    stats.watchdog_trips[0] - trips, before_pids, pids()))
  io.stdout:flush()
end

assert(wait_for(walking, 90), 'the robot did not walk within 90 s of start')
print(string.format('start walking at t=%.2f dcm=%d period_ms=%.3f', sensor.time[0], sensor.dcm_pid[0],
  sensor.period[0] * 1e3))
for _, fault in ipairs(faults) do
  sleep(0.5 + 2.5 * math.random())
  if not walking() then wait_for(walking, 30) end
  run_fault(fault)
end
print(string.format('end t=%.2f dcm=%d motion_tick=%d sensor_tick=%d', sensor.time[0], sensor.dcm_pid[0],
  motion.tick[0], sensor.tick[0]))
