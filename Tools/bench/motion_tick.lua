-- Benchmark: compute time of one motion tick (walk generator + leg IK + feedback + COM from the
-- mass model, i.e. Player/Motion/control.lua's walk state) in LuaJIT, robot-free.
-- usage: luajit Tools/bench/motion_tick.lua [ticks]   prints median, p99, max in microseconds.
local Config = require('Config')
local kin = require('kinematics')
local shm = require('shm')
local control = require('Motion.control')

local n = tonumber(arg and arg[1]) or 50000
local robot = Config.load('robot')
local c = control.new({ robot = robot, params = Config.load('walk'), model = kin.load() })
local dt = robot.period
local now = shm.C.shm_now
-- stance first, then walking with a command that changes now and then (all branches warm)
for _ = 1, 200 do
  for i = 1, c.n do c.pos[i] = c.q[i] end
  c:tick(c.t + dt)
end
c:request('walk')
local times = {}
math.randomseed(1)
for k = 1, n do
  if k % 500 == 0 then
    c.vel_cmd[1], c.vel_cmd[2], c.vel_cmd[3] = math.random() * 0.3, math.random() * 0.1 - 0.05, math.random() - 0.5
  end
  for i = 1, c.n do c.pos[i] = c.q[i] end
  c.gyro[1], c.gyro[2] = 0.05 * math.sin(k * 0.1), 0.05 * math.cos(k * 0.1)
  local t0 = now()
  c:tick(c.t + dt)
  times[k] = (now() - t0) * 1e6
end
assert(c:state() == 'walk', 'not walking: ' .. c:state())
table.sort(times)
print(string.format('motion tick (walk + IK + feedback + COM), %d ticks: median %.1f us, p99 %.1f us, max %.1f us',
  n, times[math.floor(n * 0.5)], times[math.floor(n * 0.99)], times[n]))
