-- A lockstep participant like the motion process: every tick it waits for dcm.sensor as motion
-- does (Body.wait_tick), reads the sensors, commands the stance through Body and reports the tick
-- done. Used by Tools/bench/sim_lockstep.sh.
--   luajit Tools/bench/sim_participant.lua SIM_SECONDS
local shm = require('shm')
local Body = require('Body')
local lockstep = require('lockstep')
local stance = dofile(os.getenv('HRP_ROOT') .. '/Tests/sim/stance.lua')

local seconds = tonumber(arg[1]) or 30
local C = shm.C
local q = stance.pose()
local names = Body.joint_names()

local p = lockstep.join()
local tick = Body.get_tick()   -- the DCM holds this tick until our first done()
local first_tick, t0 = tick, C.shm_now()
local last = first_tick + math.floor(seconds / Body.period() + 0.5)
-- wall time spent on our side of a tick (from seeing it to reporting it done) and between ticks
local busy, idle, seen = 0, 0, t0
while true do
  -- the motion process's work in miniature: read sensors, write 20 commands
  local _ = Body.get_gyro()
  for i = 1, #names do Body.set_command(names[i], q[names[i]] or 0) end
  Body.actuator.tick_ack[0] = tick
  if tick >= last then break end
  p:done(tick)
  local t_done = C.shm_now()
  busy = busy + (t_done - seen)
  tick = Body.wait_tick(tick, 1.0) or tick
  seen = C.shm_now()
  idle = idle + (seen - t_done)
end
local wall = C.shm_now() - t0
local n = tick - first_tick
local sim = n * Body.period()
p:leave()
print(string.format('lockstep: %.1f s simulated in %.2f s wall: real-time factor %.1f (%d ticks, %.0f ticks/s)',
  sim, wall, sim / wall, n, n / wall))
print(string.format('participant: per tick %.1f us from seeing the tick to reporting it done, %.1f us until the next',
  1e6 * busy / math.max(n, 1), 1e6 * idle / math.max(n, 1)))
