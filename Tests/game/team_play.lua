-- Two robots of one team in one simulated world (run by ./run_repl on the first robot's lockstep,
-- team_test.sh): they hear each other over UDP (the league's message), the one nearer the ball
-- strikes and the other defends; when the striker's processes are killed, the defender takes its
-- role over after team.lost_after and goes for the ball. Prints "check NAME ok|FAIL detail" lines.
--   ./run_repl Tests/game/team_play.lua PIDFILE_OF_ROBOT_2
-- luacheck: globals Sim wait arg shm Body
local ffi = require('ffi')
local gc_sim = require('Tests.game.gc_sim')
local roles = require('Team.roles')
local Config = require('Config')
ffi.cdef [[ int kill(int pid, int sig); ]]

local pidfile = arg[1]
assert(pidfile, 'usage: team_play.lua PIDFILE_OF_ROBOT_2')
local rules = Config.load('game')
local other = shm.robot_id() + 1
local game1, game2 = shm.open('game'), shm.open('game', { robot = other })
local team1, team2 = shm.open('team'), shm.open('team', { robot = other })
local sim2, sync = shm.open('sim', { robot = other }), shm.open('sync')

local function check(name, ok, detail)
  print(string.format('check %s %s %s', name, ok and 'ok' or 'FAIL', detail))
  io.stdout:flush()
end

-- Sim.teleport_robot for the other robot: the same request on its sim block
local function teleport_other(x, y, yaw)
  sim2:write(function(s)
    s.request[0] = 2
    s.args[0], s.args[1], s.args[2], s.args[3] = x, y, yaw, 0
    s.request_seq[0] = s.request_seq[0] + 1
  end)
  shm.C.shm_fetch_add_u32(sync.done_count, 1)
  shm.C.shm_futex_wake(sync.done_count)
end

local function role(g) return roles.ROLES[g.role[0]] or tostring(g.role[0]) end
local function truth2() return sim2.robot[0], sim2.robot[1] end

gc_sim.joined(4)
gc_sim.joined(3, other)
Sim.teleport_robot(-3.0, -1.0, 0.0)
teleport_other(-1.5, 1.0, 0.0)
Sim.teleport_ball(-0.5, 1.2)
wait(12)
check('hear_each_other', team1.fresh[1] == 1 and team2.fresh[0] == 1 and team1.foreign[0] == 0,
  string.format('robot 1 heard %d messages (fresh %d), robot 2 heard %d (fresh %d); malformed %d/%d',
    team1.received[0], team1.fresh[1], team2.received[0], team2.fresh[0], team1.malformed[0], team2.malformed[0]))
local x2, y2 = truth2()
check('roles', role(game1) == 'defender' and role(game2) == 'striker',
  string.format('robot 1 %s, robot 2 %s (robot 2 at %.2f, %.2f)', role(game1), role(game2), x2, y2))

-- the striker's processes die: the defender takes over
local f = assert(io.open(pidfile))
local pid = tonumber(f:read('*l'))
f:close()
ffi.C.kill(pid, 15)
local t0 = Body.get_time()
local took
local T = Sim.truth()
local d0 = math.sqrt((T.x - T.ball.x) ^ 2 + (T.y - T.ball.y) ^ 2)
while Body.get_time() - t0 < rules.team.lost_after + 3 do
  wait(0.1)
  if not took and role(game1) == 'striker' then took = Body.get_time() - t0 end
end
check('takes_over', took ~= nil and took >= rules.team.lost_after - 0.5,
  string.format('robot 1 striker %s s after robot 2 went silent (lost after %.1f s)', tostring(took),
    rules.team.lost_after))
wait(15)
T = Sim.truth()
local d1 = math.sqrt((T.x - T.ball.x) ^ 2 + (T.y - T.ball.y) ^ 2)
local moved = math.abs(T.ball.x + 0.5) + math.abs(T.ball.y - 1.2) > 0.1
check('goes_for_ball', d1 < d0 - 1.0 or moved,
  string.format('robot 1 to the ball %.2f m -> %.2f m (ball moved: %s)', d0, d1, tostring(moved)))
