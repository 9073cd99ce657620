-- run_main restarted during PLAYING (run by ./run_repl inside the sim's lockstep, restart_test.sh):
--   ./run_repl Tests/game/restart_play.lua GC_PORT PIDFILE
-- Acts as the GameController (PLAYING packets every 0.5 s of robot time on GC_PORT), lets the robot
-- play until it walks, kills run_main (its pid in PIDFILE) and starts it again ($RESTART_CMD, which
-- writes the new pid to PIDFILE), then measures the robot time from the new processes' start until
-- the robot walks again. Prints "result walking_after=T moved=M" (T = -1: not within 10 s).
-- luacheck: globals Sim wait arg shm Body motion game
local ffi = require('ffi')
local packet = require('GameFSM.packet')
local gc_sim = require('Tests.game.gc_sim')
ffi.cdef [[ int kill(int pid, int sig); int usleep(unsigned int usec); ]]

local port, pidfile = tonumber(arg[1]), arg[2]
assert(port and pidfile and os.getenv('RESTART_CMD'), 'usage: RESTART_CMD=... restart_play.lua GC_PORT PIDFILE')
local gc = gc_sim.new(port, nil, require('Config').load('behavior').team_number)
gc.packet = { state = packet.STATE.playing }
local joined = gc_sim.joined
local function read_pid()
  local f = assert(io.open(pidfile))
  local pid = tonumber(f:read('*l'))
  f:close()
  return pid
end

joined(4)
Sim.teleport_robot(-2.0, 0.0, 0.0)
Sim.teleport_ball(-1.0, 0.3)
-- play until the robot walks
local t0 = Body.get_time()
repeat gc:tick() wait(0.1) until motion.walking[0] == 1 or Body.get_time() - t0 > 20
assert(motion.walking[0] == 1, 'the robot did not walk within 20 s of PLAYING')
wait(2.0)
print(string.format('walking at t=%.2f; restarting run_main', Body.get_time() - t0))

-- kill run_main (it stops its processes) and start it again; the clock holds while no one waits
local old = read_pid()
ffi.C.kill(old, 15)
while ffi.C.kill(old, 0) == 0 do ffi.C.usleep(20000) end
assert(os.execute(os.getenv('RESTART_CMD')) == 0, 'RESTART_CMD failed')
joined(4)
local t1 = Body.get_time()
local T1 = Sim.truth()
local walking_after = -1
while Body.get_time() - t1 < 10 do
  gc:tick()
  wait(0.05)
  local names = require('BodyFSM.machine').states
  print(string.format('t=%.2f game=%d body=%s motion=%s walking=%d', Body.get_time() - t1, game.state[0],
    names[game.body_state[0] + 1] or '?', require('Motion').state(), motion.walking[0]))
  if motion.walking[0] == 1 and game.state[0] == packet.STATE.playing then
    walking_after = Body.get_time() - t1
    break
  end
end
-- and it really moves (3 s more)
for _ = 1, 60 do gc:tick() wait(0.05) end
local T2 = Sim.truth()
print(string.format('result walking_after=%.2f moved=%.2f', walking_after,
  math.sqrt((T2.x - T1.x) ^ 2 + (T2.y - T1.y) ^ 2)))
