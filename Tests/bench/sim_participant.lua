-- A lockstep participant like the motion process: every tick it reads the sensors, commands the
-- stance through Body and reports the tick done. Used by Tests/bench/sim_lockstep.sh.
--   luajit Tests/bench/sim_participant.lua SIM_SECONDS
local ffi = require('ffi')
local shm = require('shm')
local Body = require('Body')
local lockstep = require('lockstep')
local stance = dofile(os.getenv('HRP_ROOT') .. '/Tests/sim/stance.lua')

local seconds = tonumber(arg[1]) or 30
local sync = shm.open('sync')
local C = shm.C
local tick_word = ffi.cast('volatile uint32_t *', sync.tick)
local q = stance.pose()
local names = Body.joint_names()

local p = lockstep.join()
local tick = tick_word[0]
local first_tick, t0 = tick, C.shm_now()
local last = first_tick + math.floor(seconds / Body.period() + 0.5)
while true do
  -- the motion process's work in miniature: read sensors, write 20 commands
  local _ = Body.get_gyro()
  for i = 1, #names do Body.set_command(names[i], q[names[i]] or 0) end
  Body.actuator.tick_ack[0] = tick
  if tick >= last then break end
  p:done(tick)
  while tick_word[0] == tick do C.shm_futex_wait(tick_word, tick, 0.5) end
  tick = tick_word[0]
end
local wall = C.shm_now() - t0
local sim = (tick - first_tick) * Body.period()
p:leave()
print(string.format('lockstep: %.1f s simulated in %.2f s wall: real-time factor %.1f (%d ticks, %.0f ticks/s)',
  sim, wall, sim / wall, tick - first_tick, (tick - first_tick) / wall))
