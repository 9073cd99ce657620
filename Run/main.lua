-- The process manager behind ./run_main: starts the robot's Lua processes for ROBOT_ID, prints one
-- status line per second, restarts a process that ends (the robot is held in a safe stance
-- meanwhile) and stops everything cleanly on Ctrl-C / SIGTERM.
--
--   ./run_main                      motion, vision and behavior
--   ./run_main motion [vision ...]  a subset
--   ./run_main --sim [names]        also starts the simulator (./run_dcm) first: one robot, headless
--   ./run_main --record [DIR]       also records every shm block into MCAP files (Run/recorder; DIR, else
--                                   Config's recorder.dir)
--   ./run_main --view [PORT]        also serves the live view (./run_view; PORT, default 8080; it prints the URL)
--   options: --dcm-arg ARG (repeatable, passed to ./run_dcm), --no-restart, --quiet,
--            --script NAME=FILE (run FILE, relative to the repository root, as process NAME),
--            --hang-after S (default 2; 0: off): a process that makes no progress while its input
--            moves on for S s of robot time is killed and restarted (Run/hang.lua)
--
-- A process X is `luajit Player/X/main.lua` (behavior: Player/Behavior/main.lua); one that does not
-- exist yet is reported and skipped. Status and events go to stdout, one line each.
local shm = require('shm')
local proc = require('Run.proc')
local native = require('native')

local ROOT = native.root()
local ALL = { 'motion', 'vision', 'behavior' }
local SCRIPT = {
  motion = 'Player/Motion/main.lua',
  vision = 'Player/Vision/main.lua',
  behavior = 'Player/Behavior/main.lua',
}

local function usage(msg)
  if msg then io.stderr:write('run_main: ', msg, '\n') end
  io.stderr:write('usage: ./run_main [--sim] [--record [DIR]] [--view [PORT]] [--dcm-arg ARG]...',
    ' [--script NAME=FILE]... [--no-restart] [--quiet] [--hang-after S] [motion|vision|behavior]...\n')
  os.exit(2)
end

-- ---- arguments
local opts = { names = {}, sim = false, dcm_args = {}, restart = true, quiet = false, record = false,
  hang_after = 2.0 }
do
  local args = { ... }
  local i = 1
  while i <= #args do
    local a = args[i]
    if a == '--sim' then opts.sim = true
    elseif a == '--record' then
      opts.record = true
      local dir = args[i + 1]
      if dir and dir:sub(1, 1) ~= '-' and not SCRIPT[dir] then opts.record_dir, i = dir, i + 1 end
    elseif a == '--view' then
      opts.view = '8080'
      local port = args[i + 1]
      if port and port:match('^%d+$') then opts.view, i = port, i + 1 end
    elseif a == '--dcm-arg' then
      i = i + 1
      if not args[i] then usage('--dcm-arg needs a value') end
      opts.dcm_args[#opts.dcm_args + 1] = args[i]
    elseif a == '--script' then
      i = i + 1
      local name, file = (args[i] or ''):match('^(%w+)=(.+)$')
      if not name then usage('--script needs NAME=FILE') end
      SCRIPT[name] = file
    elseif a == '--hang-after' then
      i = i + 1
      opts.hang_after = tonumber(args[i])
      if not opts.hang_after or opts.hang_after < 0 then usage('--hang-after needs a number of seconds >= 0') end
    elseif a == '--no-restart' then opts.restart = false
    elseif a == '--quiet' then opts.quiet = true
    elseif a == '-h' or a == '--help' then usage()
    elseif SCRIPT[a] then opts.names[#opts.names + 1] = a
    else usage("unknown process or option '" .. a .. "'") end
    i = i + 1
  end
  -- under Replay the body and its motion are the recording's (Config/platforms/Replay/dcm.lua)
  if #opts.names == 0 then opts.names = os.getenv('PLATFORM') == 'Replay' and { 'vision', 'behavior' } or ALL end
end

local function log(fmt, ...)
  io.stdout:write('[main] ', string.format(fmt, ...), '\n')
  io.stdout:flush()
end

local function file_exists(path)
  local f = io.open(path, 'r')
  if f then f:close() return true end
  return false
end

proc.block_signals()

local sensor = shm.open('dcm.sensor')
local stats = shm.open('dcm.stats')
local motion = shm.open('motion')
local vision = shm.open('vision')
local world = shm.open('world')
local game = shm.open('game')
local sim = opts.sim and shm.open('sim') or nil
-- live parameter changes (Lib/param.lua) last as long as this run: a process it restarts applies
-- them again, a new run_main starts from the config files (param.save() keeps a change)
require('param').reset()

-- hang detection: each process's progress counter against the input it works on
local hangs
if opts.hang_after > 0 then
  local image = shm.open('camera.image')
  hangs = require('Run.hang').new(opts.hang_after, {
    motion = { progress = function() return motion.tick[0] end, input = function() return sensor.tick[0] end },
    vision = { progress = function() return vision.frame[0] end, input = function() return image.frame[0] end },
    behavior = { progress = function() return game.time[0] end, input = function() return sensor.tick[0] end },
  })
end

-- ---- the children
-- child = { name, argv, pid, started (wall s), restarts, next_start (wall s) }
local children = {}
local by_pid = {}

local function start(child)
  local pid, err = proc.spawn(child.argv)
  if not pid then
    log('%s: cannot start: %s', child.name, err)
    child.next_start = shm.C.shm_now() + 2
    return false
  end
  child.pid, child.started, child.next_start = pid, shm.C.shm_now(), nil
  by_pid[pid] = child
  if hangs then hangs:started(child.name, sensor.time[0]) end
  log('%s started (pid %d)', child.name, pid)
  return true
end

if opts.sim then
  children[#children + 1] = { name = 'dcm', argv = { ROOT .. '/run_dcm', unpack(opts.dcm_args) },
    restarts = 0 }
end
if opts.record then
  local argv = { ROOT .. '/build/bin/hrp_record', '--quiet' }
  if opts.record_dir then argv[3], argv[4] = '--dir', opts.record_dir end
  children[#children + 1] = { name = 'recorder', argv = argv, restarts = 0 }
end
if opts.view then
  children[#children + 1] = { name = 'view', argv = { ROOT .. '/run_view', '--port', opts.view }, restarts = 0 }
end
for _, name in ipairs(opts.names) do
  local script = SCRIPT[name]:sub(1, 1) == '/' and SCRIPT[name] or ROOT .. '/' .. SCRIPT[name]
  if file_exists(script) then
    children[#children + 1] = { name = name, argv = { 'luajit', script }, restarts = 0 }
  else
    log('%s: %s does not exist yet: not started', name, SCRIPT[name])
  end
end

-- optional name tables (present once the other parts exist)
local function try_require(name)
  local ok, mod = pcall(require, name)
  if ok then return mod end
  return nil
end
local body_machine = try_require('BodyFSM.machine')
local head_machine = try_require('HeadFSM.machine')
local roles = try_require('Team.roles')
local Motion -- loaded lazily: it opens blocks and reads config
local motion_loaded = false
local function motion_api()
  if not motion_loaded then
    motion_loaded = true
    local ok, mod = pcall(require, 'Motion')
    if ok and type(mod) == 'table' then Motion = mod end
  end
  return Motion
end

local GAME_STATES = { [0] = 'initial', 'ready', 'set', 'playing', 'finished' }

-- The robot stands still while a process is missing: zero walk velocity and a stand request
-- (the motion process keeps the robot's last commands while it itself restarts; the DCM holds them).
local function safe_stance(why)
  local m = motion_api()
  local ok = false
  if m and m.request then ok = pcall(m.request, 'stand') end
  motion:set('velocity', { 0, 0, 0 })
  log('safe stance (%s)%s', why, ok and '' or ': motion API not available, walk velocity zeroed')
end

-- ---- start: the DCM first (and wait until its clock runs, or until it holds the clock for the
-- lockstep's participants), then the Lua processes
local sync = shm.open('sync')
for _, child in ipairs(children) do
  if child.name == 'dcm' then
    start(child)
    local tick0 = sensor.tick[0]
    local deadline = shm.C.shm_now() + 20
    -- (./run_dcm execs the DCM: its pid is the child's)
    local function holds() return sync.lockstep[0] == 1 and sensor.dcm_pid[0] == child.pid end
    while sensor.tick[0] == tick0 and not holds() and shm.C.shm_now() < deadline do
      local sig = proc.wait_signal(0.05)
      if sig == 'INT' or sig == 'TERM' then proc.signal(child.pid, proc.SIGTERM) os.exit(130) end
      if sig == 'CHLD' then
        for pid, how in proc.reap() do
          if pid == child.pid then log('dcm ended during start-up (%s)', how) os.exit(1) end
        end
      end
    end
    if sensor.tick[0] == tick0 and not holds() then log('dcm: clock not advancing after 20 s') end
  end
end
for _, child in ipairs(children) do
  if child.name ~= 'dcm' then start(child) end
end
if #children == 0 then log('nothing to run') os.exit(1) end

-- ---- status line
local last_frame, last_frame_wall = vision.frame[0], shm.C.shm_now()
local function status()
  local parts = {}
  parts[#parts + 1] = string.format('t=%.1f', sensor.time[0])
  local gs = GAME_STATES[game.state[0]] or tostring(game.state[0])
  parts[#parts + 1] = string.format('game=%s%s', gs, game.penalized[0] ~= 0 and '(penalized)' or '')
  if roles and roles.ROLES[game.role[0]] then parts[#parts + 1] = 'role=' .. roles.ROLES[game.role[0]] end
  if sim then parts[#parts + 1] = string.format('score=%d:%d', sim.score[0], sim.score[1]) end
  local m = motion_api()
  local mstate
  if m and m.state then
    local ok, s = pcall(m.state)
    mstate = ok and tostring(s) or '?'
  else
    mstate = tostring(motion.state[0])
  end
  parts[#parts + 1] = 'motion=' .. mstate
  local function state_name(machine, idx)
    if machine and machine.states and machine.states[idx + 1] then return machine.states[idx + 1] end
    return tostring(idx)
  end
  parts[#parts + 1] = 'body=' .. state_name(body_machine, game.body_state[0])
  parts[#parts + 1] = 'head=' .. state_name(head_machine, game.head_state[0])
  local age = sensor.time[0] - world.ball_time[0]
  if world.ball_time[0] > 0 and age < 1.0 then
    parts[#parts + 1] = string.format('ball=(%.2f,%.2f)', world.ball[0], world.ball[1])
  elseif vision.ball_detected[0] ~= 0 then
    parts[#parts + 1] = string.format('ball=(%.2f,%.2f)v', vision.ball_position[0], vision.ball_position[1])
  else
    parts[#parts + 1] = 'ball=none'
  end
  parts[#parts + 1] = string.format('pose=(%.2f,%.2f,%d)', world.pose[0], world.pose[1],
    math.floor(math.deg(world.pose[2]) + 0.5))
  local now = shm.C.shm_now()
  local fps = vision.fps[0]
  if fps <= 0 and now > last_frame_wall then
    fps = (vision.frame[0] - last_frame) / (now - last_frame_wall)
  end
  last_frame, last_frame_wall = vision.frame[0], now
  parts[#parts + 1] = string.format('vision=%.1ffps', fps)
  parts[#parts + 1] = string.format('dcm=%.0fHz', stats.rate[0])
  if sim then parts[#parts + 1] = string.format('x%.1f', sim.realtime_factor[0]) end
  local down = {}
  for _, c in ipairs(children) do if not c.pid then down[#down + 1] = c.name end end
  if #down > 0 then parts[#parts + 1] = 'DOWN:' .. table.concat(down, ',') end
  io.stdout:write(table.concat(parts, ' '), '\n')
  io.stdout:flush()
end

-- ---- stop everything: SIGTERM to every child (Lua processes first, the DCM last), SIGKILL after 3 s
local function stop_all(code)
  log('stopping')
  local order = {}
  for i = #children, 1, -1 do order[#order + 1] = children[i] end
  for _, c in ipairs(order) do
    if c.pid then proc.signal(c.pid, proc.SIGTERM) end
  end
  local deadline = shm.C.shm_now() + 3
  while shm.C.shm_now() < deadline do
    for pid, how in proc.reap() do
      local c = by_pid[pid]
      if c then c.pid = nil; by_pid[pid] = nil; log('%s stopped (%s)', c.name, how) end
    end
    local any = false
    for _, c in ipairs(children) do if c.pid then any = true end end
    if not any then break end
    proc.wait_signal(0.05)
  end
  for _, c in ipairs(children) do
    if c.pid then
      proc.signal(c.pid, proc.SIGKILL)
      log('%s killed', c.name)
    end
  end
  for _ in proc.reap() do end
  os.exit(code)
end

-- ---- main loop
local next_status = shm.C.shm_now() + 1
-- a block replaced under us (removed, or recreated with another layout): read what is there now
-- (the children holding it exit, naming it, and are restarted: Lib/shm_watch.lua)
local check_blocks = require('shm_watch').reopen_replaced(log)
while true do
  check_blocks()
  local now = shm.C.shm_now()
  local wait = next_status - now
  for _, c in ipairs(children) do
    if not c.pid and c.next_start then wait = math.min(wait, c.next_start - now) end
  end
  local sig = proc.wait_signal(math.max(0.001, wait))
  if sig == 'INT' or sig == 'TERM' then stop_all(0) end
  for pid, how in proc.reap() do
    local c = by_pid[pid]
    if c then
      by_pid[pid] = nil
      c.pid = nil
      local ran = shm.C.shm_now() - c.started
      if opts.restart then
        -- back off when it keeps failing fast: 1 s, then doubling up to 10 s
        c.backoff = (ran < 5 and c.backoff) and math.min(10, c.backoff * 2) or 1
        c.next_start = shm.C.shm_now() + c.backoff
        log('%s ended (%s) after %.1f s: restarting in %.0f s', c.name, how, ran, c.backoff)
      else
        log('%s ended (%s) after %.1f s', c.name, how, ran)
      end
      if c.name ~= 'dcm' and c.name ~= 'recorder' and c.name ~= 'view' then safe_stance(c.name .. ' down') end
    end
  end
  if hangs then
    local name, stalled = hangs:check(sensor.time[0])
    for _, c in ipairs(children) do
      if c.name == name and c.pid then
        log('%s (pid %d) made no progress for %.1f s of robot time: killing it', name, c.pid, stalled)
        proc.signal(c.pid, proc.SIGKILL)   -- reaped and restarted above on the next round
      end
    end
  end
  now = shm.C.shm_now()
  local alive = 0
  for _, c in ipairs(children) do
    if not c.pid and c.next_start and now >= c.next_start then
      c.restarts = c.restarts + 1
      start(c)
    end
    if c.pid or c.next_start then alive = alive + 1 end
  end
  if alive == 0 then log('every process has ended') stop_all(1) end
  if now >= next_status then
    if not opts.quiet then status() end
    next_status = next_status + 1
    if next_status < now then next_status = now + 1 end
  end
end
