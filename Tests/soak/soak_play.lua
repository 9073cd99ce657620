-- The soak's GameController and sampler (run by ./run_repl inside the sim's lockstep, Tests/soak/soak.sh):
--   ./run_repl Tests/soak/soak_play.lua SECONDS RESTART_EVERY GC_PORT MAIN_PID [SAMPLE_EVERY]
-- Plays SECONDS of robot time; every RESTART_EVERY s the game restarts (INITIAL, READY, SET, PLAYING, the
-- ball and the robot put back); at the start the robot is jostled (below). At the start and every SAMPLE_EVERY
-- s of robot time (default 30) samples each of run_main's children (the DCM too): resident memory, its
-- anonymous and huge-page parts, open file descriptors, mapped hrp shm segments; prints one line per process
-- ("proc motion t=30 pid=.. rss_kb=.. anon_kb=.. huge_kb=.. fds=.. shm=..") and one for the robot ("robot
-- t=30 segments=.. games=.. falls=.."), judged by Tests/soak/soak.sh and Tests/soak/rss_check.lua.
-- Every fall is classified by the fall census (Tools/match/census.lua) from the sim's truth at each look
-- (a "fall ..." line each, the census table at the end; SOAK_FALLS=FILE writes the falls there as CSV).
-- SOAK_SMAPS=DIR also copies each process's /proc/PID/smaps there at each sample (where the bytes are).
-- luacheck: globals Sim wait arg shm Body motion game
local packet = require('GameFSM.packet')
local gc_sim = require('Tests.game.gc_sim')
local census_mod = require('Tools.match.census')
local Motion = require('Motion')

local seconds, every, port, main_pid = tonumber(arg[1]), tonumber(arg[2]), tonumber(arg[3]), tonumber(arg[4])
local sample_every = tonumber(arg[5]) or 30
assert(seconds and every and port and main_pid, 'usage: soak_play.lua SECONDS RESTART_EVERY GC_PORT MAIN_PID [SAMPLE]')
local gc = gc_sim.new(port, nil, require('Config').load('behavior').team_number)
local S = packet.STATE
local sim_config = require('Config').load('sim')
local census = census_mod.new(require('Config').load('game').referee.census, { 'robot' }, {
  length = sim_config.field.length, goal_width = sim_config.goal.width, goal_depth = sim_config.goal.depth })
local smaps_dir = os.getenv('SOAK_SMAPS')

local function read(path)
  local f = io.open(path)
  if not f then return nil end
  local s = f:read('*a')
  f:close()
  return s
end
local function children()
  local list = {}
  for pid in (read(string.format('/proc/%d/task/%d/children', main_pid, main_pid)) or ''):gmatch('%d+') do
    local cmd = (read('/proc/' .. pid .. '/cmdline') or ''):gsub('%z', ' ')
    local name = cmd:match('Player/(%a+)/main%.lua') or (cmd:find('dcm_', 1, true) and 'dcm') or cmd
    list[#list + 1] = { pid = tonumber(pid), name = name:lower() }
  end
  return list
end

local t_start = Body.get_time()
local games, falls0 = 0, motion.falls[0]
local function sample()
  local t = Body.get_time() - t_start
  for _, c in ipairs(children()) do
    local status = read('/proc/' .. c.pid .. '/status') or ''
    local rollup = read('/proc/' .. c.pid .. '/smaps_rollup') or ''
    local fds = 0
    local p = io.popen('ls /proc/' .. c.pid .. '/fd 2>/dev/null')
    for _ in p:lines() do fds = fds + 1 end
    p:close()
    local maps = read('/proc/' .. c.pid .. '/maps') or ''
    local segs = {}
    for seg in maps:gmatch('/dev/shm/(hrp%.[%w%._]+)') do segs[seg] = true end
    local nseg = 0
    for _ in pairs(segs) do nseg = nseg + 1 end
    print(string.format('proc %s t=%.0f pid=%d rss_kb=%d anon_kb=%d huge_kb=%d fds=%d shm=%d', c.name, t, c.pid,
      tonumber(status:match('VmRSS:%s*(%d+)')) or -1, tonumber(rollup:match('\nAnonymous:%s*(%d+)')) or -1,
      tonumber(rollup:match('\nAnonHugePages:%s*(%d+)')) or -1, fds, nseg))
    if smaps_dir then
      local f = io.open(string.format('%s/%s.%04.0f.smaps', smaps_dir, c.name, t), 'w')
      if f then f:write(read('/proc/' .. c.pid .. '/smaps') or '') f:close() end
    end
  end
  local all = 0
  local p = io.popen('ls /dev/shm 2>/dev/null')
  for name in p:lines() do if name:find('^hrp%.' .. shm.robot_id() .. '%.') then all = all + 1 end end
  p:close()
  print(string.format('robot t=%.0f segments=%d games=%d falls=%d', t, all, games, motion.falls[0] - falls0))
  io.stdout:flush()
end

gc_sim.joined(4)
local next_sample = sample_every
local function census_look()
  local T = Sim.truth()
  local f = census:look(1, { t = Body.get_time() - t_start, x = T.x, y = T.y, yaw = T.yaw, roll = T.roll,
    pitch = T.pitch, fallen = T.fallen, state = Motion.STATES[motion.state[0] + 1], kick = motion.kick_phase[0] == 2,
    cmd = { motion.velocity[0], motion.velocity[1], motion.velocity[2] }, ball = { T.ball.x, T.ball.y }, others = {} })
  if f then print(string.format('%8.1f  %s', f.t, census_mod.line(f))) io.stdout:flush() end
end

local function play_for(s)
  local t0 = Body.get_time()
  while Body.get_time() - t0 < s do
    gc:tick()
    wait(0.1)
    census_look()
    if Body.get_time() - t_start >= next_sample - 1e-6 then
      sample()
      next_sample = next_sample + sample_every
    end
  end
end
-- The sim camera's widest motion blur: its planes (Platforms/Sim/develop.cpp) grow to the widest blur seen
-- so far, up to three frame widths (2 MB more of the DCM's RSS), which a game restart's teleport gives when
-- it falls inside a frame's 10 ms exposure (by chance: in some runs at the first restart, in others at the
-- third). Here the robot turns on the spot by 1.5 rad and back every tick for more than a camera period, so
-- that a frame's exposure surely spans a jump across the whole image, before the warm-up ends.
local function jostle()
  for k = 1, 12 do
    Sim.teleport_robot(-2.0, 0.0, k % 2 == 0 and 0.0 or 1.5)
    wait(0.008)
  end
end
local function restart_game()
  games = games + 1
  Sim.teleport_robot(-2.0, 0.0, 0.0)
  Sim.teleport_ball(0.0, 0.0)
  for _, st in ipairs({ S.initial, S.ready, S.set }) do gc:set({ state = st }) play_for(1.0) end
  gc:set({ state = S.playing })
end

sample()
jostle()
local walked = 0
while Body.get_time() - t_start < seconds - 1e-6 do
  local left = seconds - (Body.get_time() - t_start)
  restart_game()
  play_for(math.min(every, left) - 3.0)
  if motion.walking[0] == 1 then walked = walked + 1 end
end
if next_sample <= seconds + 1e-6 then sample() end
for _, line in ipairs(census:table((Body.get_time() - t_start) / 60)) do print(line) end
local falls_path = os.getenv('SOAK_FALLS')
if falls_path and falls_path ~= '' then census:write_csv(falls_path) end
local plus, minus = Sim.score()
print(string.format('result seconds=%.0f games=%d goals=%d:%d falls=%d walking_at_restarts=%d game_state=%d frames=%d',
  Body.get_time() - t_start, games, plus, minus, motion.falls[0] - falls0, walked, game.state[0],
  shm.open('vision').frame[0]))
