-- The simulator's automatic referee: a GameController for a match of two teams in one sim world.
-- Run by ./run_repl as the lockstep's observer on the first robot (ROBOT_ID = the first robot's id):
--   ./run_repl Tools/match/referee.lua PER_TEAM GC_PORT RETURN_PORT     (rules: game.lua's `referee`; a site
--   folder, $HRP_SITE, may change them: Tools/match/match.sh)
-- With HRP_MATCH_TRACE set to a file, every look writes one line there (Tools/plot/plot_match.py):
-- "t state bx by", per robot the truth "x y yaw fallen role" (role: the game block's, -1 penalized),
-- then per robot its own view in the referee's frame: "px py pyaw ball_x ball_y ball_age body_state"
-- (its pose belief, where it believes the ball is, s since it saw it, its body FSM state's index).
-- Robots ROBOT_ID .. ROBOT_ID + 2 * PER_TEAM - 1: the first PER_TEAM are team 1's players 1..n, the
-- others team 2's. Sends GameController packets (GameFSM/packet.lua, broadcast on the loopback to
-- GC_PORT), reads the robots' return packets on RETURN_PORT, watches the sim's truth and plays the
-- game by Tools/match/rules.lua; prints the events and, at the end, the result. Every fall is classified
-- by Tools/match/census.lua from the truth and the robot's motion block (a line per fall; the census table
-- at the end); with HRP_MATCH_FALLS set to a file, the falls are written there as CSV
-- (Tools/plot/plot_falls.py).
-- luacheck: globals wait arg shm Body
local Sim = require('Sim')
local Config = require('Config')
local packet = require('GameFSM.packet')
local udp = require('GameFSM.udp')
local match = require('Tools.match.rules')
local gc_sim = require('Tests.game.gc_sim')
local tally_mod = require('Tools.match.tally')
local census_mod = require('Tools.match.census')
local Motion = require('Motion')

local n, gc_port, return_port = tonumber(arg[1]), tonumber(arg[2]), tonumber(arg[3])
assert(n and gc_port and return_port, 'usage: referee.lua PER_TEAM GC_PORT RETURN_PORT')
local rules = Config.load('game').referee
local sim = Config.load('sim')
local field = { length = sim.field.length, width = sim.field.width, goal_width = sim.goal.width,
  ball_diameter = sim.ball.diameter, penalty_mark_distance = sim.field.penalty_mark_distance,
  goal_area_length = sim.field.goal_area_length, goal_area_width = sim.field.goal_area_width }
local team_numbers = { 1, 2 }
local base = shm.robot_id()

local robots, sims, players = {}, {}, {}
for k = 1, n do players[k] = k end
for i = 1, 2 * n do
  local team = i <= n and 1 or 2
  robots[i] = { team = team, player = team == 1 and i or i - n, id = base + i - 1 }
  sims[i] = Sim.of(base + i - 1)
end
-- each robot's own view (its pose belief and role) for the per-robot figures
local beliefs = {}
for i = 1, 2 * n do beliefs[i] = { world = shm.open('world', { robot = robots[i].id }),
  game = shm.open('game', { robot = robots[i].id }), motion = shm.open('motion', { robot = robots[i].id }) } end
local tally = tally_mod.new(robots, rules.census.tip_angle)
local names = {}
for i = 1, 2 * n do names[i] = string.format('%d/%d', team_numbers[robots[i].team], robots[i].player) end
local census = census_mod.new(rules.census, names, { length = sim.field.length, goal_width = sim.goal.width,
  goal_depth = sim.goal.depth })
local m = match.new(rules, field, { { number = team_numbers[1], players = players },
  { number = team_numbers[2], players = players } })

-- every robot's three processes, and this script on the first robot
for i = 1, 2 * n do gc_sim.joined(i == 1 and 4 or 3, robots[i].id) end
local tx = assert(udp.sender())
local rx = assert(udp.listen(return_port))
local heard, bad, number, next_packet = {}, 0, 0, -1
local wall0, t0 = os.time(), Body.get_time()
local printed, sent_state, last_t = 0, nil, nil

local function look()
  local w = { robots = {} }
  for i, s in ipairs(sims) do
    local T = s.truth()
    if i == 1 then
      w.ball = { T.ball.x, T.ball.y, T.ball.vx, T.ball.vy }
      -- the physics' last contact (world index r is robot r + 1 here: match.sh starts them in order)
      w.touch = T.ball.touch >= 0 and T.ball.touch + 1 or false
      w.score = { s.score() }
    end
    w.robots[i] = { team = robots[i].team, player = robots[i].player, x = T.x, y = T.y, yaw = T.yaw,
      roll = T.roll, pitch = T.pitch, fallen = T.fallen }
  end
  return w
end

local trace_path = os.getenv('HRP_MATCH_TRACE')
local trace = trace_path and trace_path ~= '' and assert(io.open(trace_path, 'w'))
if trace then trace:write(string.format('# robots %d\n', 2 * n)) end

local function write_trace(t, w)
  local parts = { string.format('%.2f %d %.3f %.3f', t - t0, m.state, w.ball[1], w.ball[2]) }
  for i, r in ipairs(w.robots) do
    local p = m.robots[i]
    parts[#parts + 1] = string.format('%.3f %.3f %.3f %d %d', r.x, r.y, r.yaw, r.fallen and 1 or 0,
      (p and p.penalty) and -1 or beliefs[i].game.role[0])
  end
  for i, r in ipairs(w.robots) do
    local s = m.side[r.team]
    local v = beliefs[i].world:read(function(x)
      local c, sn = math.cos(x.pose[2]), math.sin(x.pose[2])
      return { x.pose[0], x.pose[1], x.pose[2], x.pose[0] + c * x.ball[0] - sn * x.ball[1],
        x.pose[1] + sn * x.ball[0] + c * x.ball[1], t - x.ball_time[0] }
    end)
    local body = beliefs[i].game.body_state[0]
    parts[#parts + 1] = string.format('%.3f %.3f %.3f %.3f %.3f %.1f %d', s * v[1], s * v[2],
      s > 0 and v[3] or v[3] + math.pi, s * v[4], s * v[5], math.min(v[6], 999), body)
  end
  trace:write(table.concat(parts, ' '), '\n')
end

local STATUS = 30 -- s of robot time between status lines (where the ball and the robots are)
local next_status = t0 + STATUS

local function status(t, w)
  local parts = { string.format('%8.1f  ball %.1f %.1f;', t - t0, w.ball[1], w.ball[2]) }
  for i, r in ipairs(w.robots) do
    parts[#parts + 1] = string.format('%d/%d %.1f %.1f%s', team_numbers[robots[i].team], r.player, r.x, r.y,
      r.fallen and ' fallen' or '')
  end
  print(table.concat(parts, ' '))
end

-- the census's record of robot i: its truth, its motion state and walk command, the ball, the others
local function census_look(t, w)
  for i, r in ipairs(w.robots) do
    local mo = beliefs[i].motion
    local others = {}
    for j, o in ipairs(w.robots) do if j ~= i then others[#others + 1] = { o.x, o.y } end end
    local f = census:look(i, { t = t - t0, x = r.x, y = r.y, yaw = r.yaw, roll = r.roll, pitch = r.pitch,
      fallen = r.fallen, state = Motion.STATES[mo.state[0] + 1], kick = mo.kick_phase[0] == 2,
      cmd = { mo.velocity[0], mo.velocity[1], mo.velocity[2] }, ball = { w.ball[1], w.ball[2] }, others = others })
    if f then print(string.format('%8.1f  %s', f.t, census_mod.line(f))) end
  end
end

while true do
  local t = Body.get_time()
  local w = look()
  census_look(t, w)
  if t >= next_status then next_status = t + STATUS status(t, w) end
  if trace then write_trace(t, w) end
  local playing = m.state == packet.STATE.playing
  for i, rb in ipairs(w.robots) do
    local b = beliefs[i]
    local bx, by, ba, side = b.world:read(function(x) return x.pose[0], x.pose[1], x.pose[2], x.pose_side[0] end)
    local p = m.robots[i]
    b.seen = { bx, by, ba, side }
    tally:look(last_t and t - last_t or 0, playing, i, rb, { x = bx, y = by, role = b.game.role[0] },
      m.side[rb.team], p and p.penalty or false)
  end
  last_t = t
  for i, rb in ipairs(w.robots) do
    local r = tally.robots[i]
    local now = r.mirrored > (r.last_mirrored or 0)
    if now ~= (r.in_mirror or false) then
      r.in_mirror = now
      local bs = beliefs[i].seen
      m:event(string.format('team %d player %d: belief %s (truth %.1f %.1f; belief %.1f %.1f %.2f, side %.2f)',
        team_numbers[rb.team], rb.player, now and 'mirrored' or 'back on its side', rb.x, rb.y, bs[1], bs[2], bs[3],
        bs[4]))
    end
    r.last_mirrored = r.mirrored
  end
  for _, a in ipairs(m:step(t, w)) do
    if a[1] == 'ball' then assert(sims[1].teleport_ball(a[2], a[3]))
    else assert(sims[a[2]].teleport_robot(a[3], a[4], a[5])) end
  end
  if t >= next_packet or m.state ~= sent_state then -- a new state at once, as the GameController does
    next_packet, sent_state = t + rules.packet_period, m.state
    local p = m:packet()
    number = (number + 1) % 256
    p.packet_number = number
    assert(tx:send(packet.build(p), '127.255.255.255', gc_port))
  end
  while true do
    local data = rx:receive()
    if not data then break end
    local r = packet.parse_return(data)
    if r then heard[r.team * 100 + r.player] = (heard[r.team * 100 + r.player] or 0) + 1 else bad = bad + 1 end
  end
  for k = printed + 1, #m.log do
    print(string.format('%8.1f  %s', m.log[k][1] - t0, m.log[k][2]))
  end
  printed = #m.log
  io.stdout:flush()
  if m.over then break end
  wait(rules.look_period)
end

if trace then trace:close() end
local st, sim_s, wall_s = m.stats, Body.get_time() - t0, math.max(1, os.time() - wall0)
print(string.format('result: team %d %d : %d team %d', team_numbers[1], m.score[1], m.score[2], team_numbers[2]))
for i = 1, 2 do
  print(string.format('team %d: goals %d, own goals %d, falls %d, penalties %d', team_numbers[i], st.goals[i],
    st.own_goals[i], st.falls[i], st.penalties[i]))
end
print(string.format('set plays: %d throw-ins, %d goal kicks, %d corner kicks', st.throw_ins, st.goal_kicks, st.corners))
local online = {}
for i = 1, 2 * n do
  local key = team_numbers[robots[i].team] * 100 + robots[i].player
  online[#online + 1] = string.format('%d/%d:%d', team_numbers[robots[i].team], robots[i].player, heard[key] or 0)
end
print('return packets (team/player:count): ' .. table.concat(online, ' ') .. (bad > 0 and ' bad ' .. bad or ''))
for _, line in ipairs(tally:lines()) do print(line) end
for _, line in ipairs(census:table(2 * n * sim_s / 60)) do print(line) end
local falls_path = os.getenv('HRP_MATCH_FALLS')
if falls_path and falls_path ~= '' then census:write_csv(falls_path) print('falls: ' .. falls_path) end
print(string.format('time: %.0f s simulated in %d s wall: real-time factor %.2f', sim_s, wall_s, sim_s / wall_s))
