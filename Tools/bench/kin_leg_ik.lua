-- Benchmark: time of leg IK from LuaJIT (one leg, and both legs into a whole-body array as the
-- walk does once per motion tick), plus leg FK and the whole-body COM. Prints median, p99 and max
-- per call in microseconds (wall clock, CLOCK_MONOTONIC); never fails on time.
--   luajit Tools/bench/kin_leg_ik.lua [samples] [robot]
local ffi = require('ffi')
local kin = require('kinematics')

ffi.cdef [[
typedef struct { long tv_sec; long tv_nsec; } kin_bench_timespec;
int clock_gettime(int clk, kin_bench_timespec *ts);
]]
local ts = ffi.new('kin_bench_timespec')
local function now_ns()
  ffi.C.clock_gettime(1, ts) -- CLOCK_MONOTONIC
  return tonumber(ts.tv_sec) * 1e9 + tonumber(ts.tv_nsec)
end

local N = tonumber(arg[1]) or 100000
local robot = arg[2] or require('Config').robot()
local m = kin.load({ robot = robot })
local p0l, p0r = m:leg_fk('l', { 0, 0, 0, 0, 0, 0 }), m:leg_fk('r', { 0, 0, 0, 0, 0, 0 })
local q = {}
for i = 1, m.n do q[i] = 0 end
local lp, rp, out = { 0, 0, 0, 0, 0, 0 }, { 0, 0, 0, 0, 0, 0 }, {}

-- A walking-like pose sequence: feet swinging back and forth, lifting, turning.
local function set_poses(i)
  local ph = (i % 200) / 200 * 2 * math.pi
  local s = math.sin(ph)
  lp[1], lp[2], lp[3] = p0l[1] + 0.04 * s, p0l[2] + 0.01, p0l[3] + 0.03 + 0.02 * math.max(0, s)
  lp[4], lp[5], lp[6] = 0.02, 0.05 * s, 0.1 * s
  rp[1], rp[2], rp[3] = p0r[1] - 0.04 * s, p0r[2] - 0.01, p0r[3] + 0.03 + 0.02 * math.max(0, -s)
  rp[4], rp[5], rp[6] = -0.02, -0.05 * s, -0.1 * s
end

local samples = ffi.new('double[?]', N)
local function report(name, f)
  for i = 1, 20000 do set_poses(i); f() end -- warm up (JIT)
  for i = 1, N do
    set_poses(i)
    local t0 = now_ns()
    f()
    samples[i - 1] = (now_ns() - t0) / 1e3
  end
  local t = {}
  for i = 0, N - 1 do t[i + 1] = samples[i] end
  table.sort(t)
  print(string.format('%-34s median %6.2f us   p99 %6.2f us   max %7.2f us   (%d calls)', name,
    t[math.floor(N / 2) + 1], t[math.floor(N * 0.99) + 1], t[N], N))
end

print(string.format('kinematics benchmark, robot %s, %d samples each', robot, N))
report('timer overhead (empty call)', function() end)
report('leg_ik, one leg', function() m:leg_ik('l', lp, out) end)
report('legs_ik, both legs (one tick)', function() m:legs_ik(lp, rp, q) end)
report('leg_fk, one leg', function() m:leg_fk('l', q, out) end)
report('com, whole body', function() m:com(q, out) end)
