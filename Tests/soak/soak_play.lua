-- The soak's GameController and sampler (run by ./run_repl inside the sim's lockstep, Tests/soak/soak.sh):
--   ./run_repl Tests/soak/soak_play.lua SECONDS RESTART_EVERY GC_PORT MAIN_PID [SAMPLE_EVERY]
-- Plays SECONDS of robot time; every RESTART_EVERY s a new game starts. The game is refereed by the sim's
-- automatic referee (Tools/match/rules.lua, the GameController of `make match`, with game.lua's `referee`
-- numbers; the robot's team against an empty one, no goalkeeper flag): INITIAL beside the touch line, READY
-- (the robot walks to its kick-off position), SET, PLAYING; after a goal READY again and the kick-off for
-- the other team, the ball back on the centre mark, as a real GameController restarts; a ball out of the
-- field gives a throw-in, goal kick or corner; a robot lying too long or leaving the field is penalized.
-- At the start the robot is jostled (below). At the start and every SAMPLE_EVERY
-- s of robot time (default 30) samples each of run_main's children (the DCM too): resident memory, its
-- anonymous and huge-page parts, open file descriptors, mapped hrp shm segments; prints one line per process
-- ("proc motion t=30 pid=.. rss_kb=.. anon_kb=.. huge_kb=.. fds=.. shm=..") and one for the robot ("robot
-- t=30 segments=.. games=.. falls=.."), judged by Tests/soak/soak.sh and Tests/soak/rss_check.lua.
-- Every fall is classified by the fall census (Tools/match/census.lua) from the sim's truth at each look
-- (a "fall ..." line each, the census table at the end; SOAK_FALLS=FILE writes the falls there as CSV);
-- falls= is the census's count (one per lying), motion_falls= the motion process's own detections.
-- The referee's events (goals, kick-offs, set plays, penalties) are printed with their robot time.
-- SOAK_SMAPS=DIR also copies each process's /proc/PID/smaps there at each sample (where the bytes are).
-- luacheck: globals Sim wait arg shm Body motion game
local packet = require('GameFSM.packet')
local gc_sim = require('Tests.game.gc_sim')
local census_mod = require('Tools.match.census')
local rules_mod = require('Tools.match.rules')
local Config = require('Config')
local Motion = require('Motion')

local seconds, every, port, main_pid = tonumber(arg[1]), tonumber(arg[2]), tonumber(arg[3]), tonumber(arg[4])
local sample_every = tonumber(arg[5]) or 30
assert(seconds and every and port and main_pid, 'usage: soak_play.lua SECONDS RESTART_EVERY GC_PORT MAIN_PID [SAMPLE]')
local beh = Config.load('behavior')
local gc = gc_sim.new(port, nil, beh.team_number)
local sim_config = Config.load('sim')
local referee = {}
for k, v in pairs(Config.load('game').referee) do referee[k] = v end
referee.goalkeeper = 0 -- the lone robot plays the field, as the soak's robot always has
local census = census_mod.new(referee.census, { 'robot' }, {
  length = sim_config.field.length, goal_width = sim_config.goal.width, goal_depth = sim_config.goal.depth })
local field = { length = sim_config.field.length, width = sim_config.field.width,
  goal_width = sim_config.goal.width, ball_diameter = sim_config.ball.diameter,
  penalty_mark_distance = sim_config.field.penalty_mark_distance,
  goal_area_length = sim_config.field.goal_area_length, goal_area_width = sim_config.field.goal_area_width }
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
local kickoffs = { 0, 0 } -- kick-offs after a goal: for the robot's team, for the other
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
  print(string.format('robot t=%.0f segments=%d games=%d falls=%d motion_falls=%d', t, all, games, #census.falls,
    motion.falls[0] - falls0))
  io.stdout:flush()
end

gc_sim.joined(4)
local next_sample = sample_every
local m, next_packet, sent_state, printed
local function new_game()
  m = rules_mod.new(referee, field, { { number = beh.team_number, players = { beh.player_number } },
    { number = gc_sim.OTHER, players = {} } })
  next_packet, sent_state, printed = -1, nil, 0
end

-- One look: the census, the referee's step (its teleports carried out), its packet when due or at once on a
-- new state (as the GameController does), its new events.
local function look()
  local T = Sim.truth()
  local t = Body.get_time() - t_start
  local f = census:look(1, { t = t, x = T.x, y = T.y, yaw = T.yaw, roll = T.roll,
    pitch = T.pitch, fallen = T.fallen, state = Motion.STATES[motion.state[0] + 1], kick = motion.kick_phase[0] == 2,
    cmd = { motion.velocity[0], motion.velocity[1], motion.velocity[2] }, ball = { T.ball.x, T.ball.y }, others = {} })
  if f then print(string.format('%8.1f  %s', f.t, census_mod.line(f))) end
  local was = m.state
  local w = { ball = { T.ball.x, T.ball.y, T.ball.vx, T.ball.vy }, touch = T.ball.touch >= 0 and 1 or false,
    score = { Sim.score() }, robots = { { team = 1, player = beh.player_number, x = T.x, y = T.y, yaw = T.yaw,
      roll = T.roll, pitch = T.pitch, fallen = T.fallen } } }
  for _, a in ipairs(m:step(Body.get_time(), w)) do
    if a[1] == 'ball' then Sim.teleport_ball(a[2], a[3]) else Sim.teleport_robot(a[3], a[4], a[5]) end
  end
  if was == packet.STATE.playing and m.state == packet.STATE.ready then
    kickoffs[m.kickoff] = kickoffs[m.kickoff] + 1
  end
  if Body.get_time() >= next_packet or m.state ~= sent_state then
    next_packet, sent_state = Body.get_time() + referee.packet_period, m.state
    local p = m:packet()
    gc.number = (gc.number + 1) % 256
    p.packet_number = gc.number
    assert(gc.tx:send(packet.build(p), '127.0.0.1', port))
  end
  for k = printed + 1, #m.log do print(string.format('%8.1f  %s', m.log[k][1] - t_start, m.log[k][2])) end
  printed = #m.log
  io.stdout:flush()
end

local function play_for(s)
  local t0 = Body.get_time()
  while Body.get_time() - t0 < s - 1e-6 do
    wait(referee.look_period)
    look()
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
  Sim.teleport_ball(0.0, 0.0)
  new_game()
end

sample()
jostle()
local walked = 0
while Body.get_time() - t_start < seconds - 1e-6 do
  local left = seconds - (Body.get_time() - t_start)
  restart_game()
  play_for(math.min(every, left))
  if motion.walking[0] == 1 then walked = walked + 1 end
end
if next_sample <= seconds + 1e-6 then sample() end
for _, line in ipairs(census:table((Body.get_time() - t_start) / 60)) do print(line) end
local falls_path = os.getenv('SOAK_FALLS')
if falls_path and falls_path ~= '' then census:write_csv(falls_path) end
local plus, minus = Sim.score()
print(string.format('result seconds=%.0f games=%d goals=%d:%d kickoffs_after_goals=%d:%d falls=%d motion_falls=%d '
  .. 'walking_at_restarts=%d game_state=%d frames=%d', Body.get_time() - t_start, games, plus, minus, kickoffs[1],
  kickoffs[2], #census.falls, motion.falls[0] - falls0, walked, game.state[0], shm.open('vision').frame[0]))
