-- The soak's GameController and sampler (run by ./run_repl inside the sim's lockstep, Tests/soak/soak.sh):
--   ./run_repl Tests/soak/soak_play.lua SECONDS RESTART_EVERY GC_PORT MAIN_PID
-- Plays SECONDS of robot time; every RESTART_EVERY s the game restarts (INITIAL, READY, SET, PLAYING, the
-- ball and the robot put back). Samples each of run_main's children (the DCM too) after the warm-up,
-- half-way and at the end: resident memory, open file descriptors, mapped hrp shm segments; prints one line per
-- process and phase ("proc motion start pid=.. rss_kb=.. fds=.. shm=..") and the robot's progress.
-- luacheck: globals Sim wait arg shm Body motion game
local packet = require('GameFSM.packet')
local gc_sim = require('Tests.game.gc_sim')

local seconds, every, port, main_pid = tonumber(arg[1]), tonumber(arg[2]), tonumber(arg[3]), tonumber(arg[4])
assert(seconds and every and port and main_pid, 'usage: soak_play.lua SECONDS RESTART_EVERY GC_PORT MAIN_PID')
local gc = gc_sim.new(port, nil, require('Config').load('behavior').team_number)
local S = packet.STATE

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
local function sample(phase)
  for _, c in ipairs(children()) do
    local status = read('/proc/' .. c.pid .. '/status') or ''
    local fds = 0
    local p = io.popen('ls /proc/' .. c.pid .. '/fd 2>/dev/null')
    for _ in p:lines() do fds = fds + 1 end
    p:close()
    local segs = {}
    for seg in (read('/proc/' .. c.pid .. '/maps') or ''):gmatch('/dev/shm/(hrp%.[%w%._]+)') do segs[seg] = true end
    local nseg = 0
    for _ in pairs(segs) do nseg = nseg + 1 end
    print(string.format('proc %s %s pid=%d rss_kb=%d fds=%d shm=%d', c.name, phase, c.pid,
      tonumber(status:match('VmRSS:%s*(%d+)')) or -1, fds, nseg))
  end
  local all = 0
  local p = io.popen('ls /dev/shm 2>/dev/null')
  for name in p:lines() do if name:find('^hrp%.' .. shm.robot_id() .. '%.') then all = all + 1 end end
  p:close()
  print(string.format('segments %s %d t=%.1f', phase, all, Body.get_time()))
  io.stdout:flush()
end

gc_sim.joined(4)
local function play_for(s)
  local t0 = Body.get_time()
  while Body.get_time() - t0 < s do gc:tick() wait(0.1) end
end
local function restart_game()
  Sim.teleport_robot(-2.0, 0.0, 0.0)
  Sim.teleport_ball(0.0, 0.0)
  for _, st in ipairs({ S.initial, S.ready, S.set }) do gc:set({ state = st }) play_for(1.0) end
  gc:set({ state = S.playing })
end

local t_start = Body.get_time()
restart_game()
play_for(math.min(30, seconds / 4))
sample('start')
local games, walked, falls0 = 1, 0, motion.falls[0]
local mid_sampled = false
while Body.get_time() - t_start < seconds do
  -- A sample half-way tells a plateau (JIT traces, heap warm-up) from a leak that grows all the time.
  if not mid_sampled and Body.get_time() - t_start >= seconds / 2 then sample('mid') mid_sampled = true end
  local left = seconds - (Body.get_time() - t_start)
  play_for(math.min(every, left))
  if motion.walking[0] == 1 then walked = walked + 1 end
  if Body.get_time() - t_start < seconds then
    games = games + 1
    restart_game()
  end
end
sample('end')
local plus, minus = Sim.score()
print(string.format('result seconds=%.0f games=%d goals=%d:%d falls=%d walking_at_restarts=%d game_state=%d frames=%d',
  Body.get_time() - t_start, games, plus, minus, motion.falls[0] - falls0, walked, game.state[0],
  shm.open('vision').frame[0]))
