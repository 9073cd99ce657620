-- The largest push survived while walking, per moment of the gait cycle, for one or more walk
-- configurations side by side in one sim run (run by Tools/tune/push_sweep.sh):
--   ./run_repl Tools/tune/push_sweep.lua DIR PHASES FORCES [LABEL=PARAMS]...
-- DIR: side (to the robot's left) or forward; PHASES: how many moments across two steps (k x
-- 2 tStep / PHASES after 3 s of walking at 0.2 m/s, the pushmax scenario's walk); FORCES: a comma
-- list (N for 0.1 s), climbed at each moment until the first fall (a single push is chaotic: the
-- spread across moments is the figure, not one bisection). LABEL=PARAMS: walk parameters as
-- WALK_PARAMS ("key=v,v;key=v"), set before that configuration's sweep and put back after it
-- (none: the config as it is). Prints per configuration "sweep LABEL k F" (the largest force
-- survived at moment k before the first fall, 0 if none) and "pushsweep LABEL min median max mean"
-- in N s. PUSH_SWEEP_ALL=1: every force at every moment (a fall at a small push does not end the
-- climb), and "pushrate LABEL" the count of moments survived per force.
-- luacheck: globals Sim Motion Walk wait Body
package.path = os.getenv('HRP_ROOT') .. '/Tests/motion/?.lua;' .. package.path
if not Sim then Sim = require('sim_shim') end -- luacheck: ignore Sim
local ks = require('kick_setup')
local sc = require('Tests.scenario_lib').new(wait, Body)
local note, wait_until = sc.note, sc.wait_until
local motion = ks.wait_for_motion(wait)
if not motion then print('not ok 1 - the motion process is not running') os.exit(1) end

local dir, phases = arg[1] or 'side', tonumber(arg[2]) or 8
local all = os.getenv('PUSH_SWEEP_ALL') == '1'
local forces = {}
for x in (arg[3] or '8,10,12,14,16,18,20,22,24'):gmatch('[^,]+') do forces[#forces + 1] = tonumber(x) end
local configs = {}
for i = 4, #arg do
  local label, params = arg[i]:match('^([^=]*)=(.*)$')
  configs[#configs + 1] = { label = label or arg[i], params = params or '' }
end
if #configs == 0 then configs[1] = { label = 'config', params = '' } end
ks.apply_walk_params(Walk, wait, note)

local function parse(params)
  local kv = {}
  for item in params:gmatch('[^;]+') do
    local key, v = item:match('^(.-)=(.*)$')
    if not key then error('push_sweep: bad parameter "' .. item .. '" (key=v,v)') end
    local vals = {}
    for x in v:gmatch('[^,]+') do vals[#vals + 1] = tonumber(x) end
    kv[#kv + 1] = { key, #vals == 1 and vals[1] or vals }
  end
  return kv
end
local function set(key, v) while not Walk.set(key, v) do wait(0.01) end end
local function copy(v)
  if type(v) ~= 'table' then return v end
  local t = {}
  for i, x in ipairs(v) do t[i] = x end
  return t
end

local T = Walk.get('tStep')
local function survives(f, k)
  ks.fresh_stance(Sim, Motion, Walk, wait, wait_until, 'push_sweep', { 4.0, -3.5 })
  Motion.request('walk')
  Walk.set_velocity(0.2, 0, 0)
  wait(3 + k * 2 * T / phases)
  return not ks.push_falls(Sim, Motion, wait_until, dir, f)
end

for _, c in ipairs(configs) do
  local kv, old = parse(c.params), {}
  for i, e in ipairs(kv) do
    old[i] = copy(Walk.get(e[1]))
    set(e[1], e[2])
  end
  local best, alive = {}, {}
  for k = 0, phases - 1 do
    local b, down = 0, false
    for i, f in ipairs(forces) do
      if down and not all then break end
      local ok = survives(f, k)
      if ok then alive[i] = (alive[i] or 0) + 1 end
      if not ok then down = true elseif not down then b = f end
    end
    best[#best + 1] = b * 0.1
    print(string.format('sweep %s %d %.1f', c.label, k, b))
    io.stdout:flush()
  end
  if all then
    local r = {}
    for i, f in ipairs(forces) do r[#r + 1] = string.format('%.1f:%d/%d', f * 0.1, alive[i] or 0, phases) end
    print(string.format('pushrate %s %s survived per push (N s: moments) %s', c.label, dir, table.concat(r, ' ')))
  end
  for i = #kv, 1, -1 do set(kv[i][1], old[i]) end
  local s = { unpack(best) }
  table.sort(s)
  local sum = 0
  for _, x in ipairs(s) do sum = sum + x end
  local n = #s
  local med = n % 2 == 1 and s[(n + 1) / 2] or 0.5 * (s[n / 2] + s[n / 2 + 1])
  print(string.format('pushsweep %s %s min %.2f median %.2f max %.2f mean %.2f N s  (per moment: %s)', c.label, dir,
    s[1], med, s[n], sum / n, table.concat(best, ' ')))
  io.stdout:flush()
end
Walk.set_velocity(0, 0, 0)
