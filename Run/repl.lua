-- The robot's REPL: LuaJIT with Config, Body, Sim (under PLATFORM=Sim) and every shm block bound.
-- Interactive with history (readline), or non-interactive with -e CODE / FILE (exit status 1 on a
-- Lua error). A non-interactive script takes part in the sim's lockstep: its wait() lets the
-- clock advance and its commands land on a defined tick.
local ffi = require('ffi')
local shm = require('shm')
local Config = require('Config')
local lockstep = require('lockstep')

local args = { ... }

local env = setmetatable({}, { __index = _G })
env.shm, env.Config = shm, Config

-- every block of this robot, by name and as a variable (dots become underscores)
local blocks = {}
for _, name in ipairs(shm.block_names()) do
  blocks[name] = shm.open(name)
  env[name:gsub('%.', '_')] = blocks[name]
end
env.blocks = blocks

local Body = require('Body')
env.Body = Body
env.history = require('history')
env.param = require('param')
env.replay = require('replay')

-- Optional modules: bound when present; a module that exists but fails to load is reported.
local function optional(name)
  local ok, mod = pcall(require, name)
  if ok then env[name] = mod return end
  if not tostring(mod):find("module '" .. name .. "' not found", 1, true) then
    io.stderr:write('repl: ', name, ' failed to load: ', tostring(mod), '\n')
  end
end
if Config.platform() == 'Sim' then optional('Sim') end
for _, name in ipairs({ 'Motion', 'Walk', 'Vision', 'World', 'Game', 'WBC', 'Teleop' }) do optional(name) end

local participant -- set in script mode

-- wait(seconds): blocks until the robot's clock has advanced that much.
function env.wait(seconds)
  seconds = seconds or 0
  if type(seconds) ~= 'number' or seconds ~= seconds or seconds < 0 then
    error('wait: seconds must be a number >= 0', 2)
  end
  local period = Body.period()
  local tick = Body.get_tick()
  local target = tick + math.max(1, math.floor(seconds / period + 0.5))
  if participant then participant:done(tick, target) end
  -- In lockstep the clock waits for every participant (and, held at tick 0, for all of them to
  -- join): while its DCM is alive a slow participant on a loaded machine is no error, up to 120 s.
  local since = shm.C.shm_now()   -- the last new tick
  local looked = since
  while tick < target do
    local t = Body.wait_tick(tick, 0.05)
    local now = shm.C.shm_now()
    if t then tick, since, looked = t, now, now end
    -- a DCM that started its lockstep after our done() (we joined first) consults us from its first
    -- tick on, whatever wake we asked for: answer it, or it waits for us for ever. Looked at every
    -- 0.05 s too: the DCM may publish its first tick before it turns the lockstep on
    if participant and tick < target and participant:due(tick) then participant:done(tick, target) end
    if now - looked >= 5.0 then
      looked = now
      local pid = tonumber(shm.open('dcm.sensor').dcm_pid[0])
      local dcm_alive = pid ~= 0 and shm.C.shm_pid_alive(pid) == 1
      if not (participant and lockstep.active() and dcm_alive and now - since < 120) then
        error(string.format('wait: the clock is not advancing (tick %d): is ./run_dcm running for ROBOT_ID %d?',
          tick, shm.robot_id()), 2)
      end
    end
  end
  if participant then participant:settle(tick) end
end

-- p(x): prints a value, tables expanded one level deep.
function env.p(x)
  if type(x) ~= 'table' then print(x) return end
  local keys = {}
  for k in pairs(x) do keys[#keys + 1] = k end
  table.sort(keys, function(a, b) return tostring(a) < tostring(b) end)
  for _, k in ipairs(keys) do
    local v = x[k]
    if type(v) == 'table' then
      local parts = {}
      for i = 1, math.min(#v, 24) do parts[i] = string.format('%.6g', tonumber(v[i]) or 0) end
      v = '{' .. table.concat(parts, ', ') .. (#v > 24 and ', ...}' or '}')
    end
    print(string.format('  %-18s %s', tostring(k), tostring(v)))
  end
end

local HELP = [[
hrp REPL (robot id %d, body %s, platform %s)
  Body.joint_names()  Body.get_position('head_pan')  Body.set_command('head_pan', 0.3)
  Body.set_head_command({pan, tilt})  Body.get_gyro()  Body.get_time()
  Motion.owners()  Body.release('head')   a Body command takes a joint motion drives, until released
  blocks['dcm.sensor']:dump()  dcm_sensor.position[0]  dcm_actuator:set('hardness', 1)
  wait(seconds)       let the robot's clock advance
  history('dcm.sensor.gyro', 2.0)   times and values of a field over the last 2 s (the recorder's ring)
  param('walk.tStep')  param('walk.tStep', 0.3)   any Config value, read / set in the running processes
  param.save()  param.list('vision.ball')  param.changes()  param.status()
  replay.pause() replay.resume() replay.step(n) replay.seek(t) replay.speed(x) replay.status()   (PLATFORM=Replay)
  p(x)                print a table
  Sim.truth() Sim.reset() Sim.teleport_robot(x, y, yaw) Sim.teleport_ball(x, y) Sim.push(fx, fy, t)
  Sim.link_truth('r_sole')   world pose of any link or frame of the body   Sim.link_names()
  Motion.request('walk')  Walk.set_velocity(vx, vy, va)  Vision.ball()   (when loaded)
  Motion.request('wbc')  WBC.set_target('r_palm', {0.35, -0.25, 0.9})  WBC.set_target('r_palm', nil)  WBC.status()
  Motion.request('wbc', { skill = 'hello_bye' })  WBC.skill('hello_bye')  WBC.skill(nil)   (skills: docs/whole-body.md)
  Motion.request('teleop')  Teleop.send(plan, wait)  Teleop.start(id)  Teleop.stop()  Teleop.status()
                      (key poses, their validation: require('teleop'), docs/teleoperation.md)
  help()  quit with Ctrl-D]]
function env.help() print(string.format(HELP, shm.robot_id(), Config.robot(), Config.platform())) end

local function run_chunk(chunk)
  setfenv(chunk, env)
  return xpcall(chunk, debug.traceback)
end

local function finish(code)
  if participant then participant:leave() end
  os.exit(code)
end

if args[1] == '-e' or (args[1] and args[1] ~= '-i') then
  local chunk, err
  if args[1] == '-e' then
    if not args[2] then io.stderr:write('repl: -e needs CODE\n') finish(2) end
    chunk, err = loadstring(args[2], '=(-e)')
    env.arg = { select(3, unpack(args)) }
  else
    chunk, err = loadfile(args[1])
    env.arg = { select(2, unpack(args)) }
  end
  if not chunk then io.stderr:write('repl: ', err, '\n') finish(1) end
  participant = lockstep.join({ observer = true })
  env.replay.participant = participant
  local ok, res = run_chunk(chunk)
  if not ok then io.stderr:write(tostring(res), '\n') finish(1) end
  finish(0)
end

-- interactive
local rl_ok, rl = pcall(ffi.load, 'readline.so.8')
if rl_ok then
  ffi.cdef [[
    char *readline(const char *prompt);
    void add_history(const char *line);
    int read_history(const char *file);
    int write_history(const char *file);
    void free(void *p);
  ]]
end
local history = (os.getenv('HOME') or '/tmp') .. '/.hrp_repl_history'
if rl_ok then rl.read_history(history) end

local function read_line(prompt)
  if not rl_ok then
    io.write(prompt) io.flush()
    return io.read('*l')
  end
  local p = rl.readline(prompt)
  if p == nil then return nil end
  local s = ffi.string(p)
  ffi.C.free(p)
  if s:match('%S') then rl.add_history(s) end
  return s
end

env.help()
while true do
  local line = read_line('hrp> ')
  if not line then break end
  local chunk = loadstring('return ' .. line, '=stdin') or select(1, loadstring(line, '=stdin'))
  if not chunk then
    local _, err = loadstring(line, '=stdin')
    print(err)
  else
    local res = { run_chunk(chunk) }
    if not res[1] then print(res[2])
    elseif #res > 1 then print(select(2, unpack(res))) end
  end
end
if rl_ok then rl.write_history(history) end
print()
finish(0)
