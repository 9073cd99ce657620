-- Tunes the kick's phases (the body's walk.lua `kick`, Config/robots/<ROBOT>) in the sim by the cross-entropy
-- method: each generation samples parameter sets around the mean, sets them in the running motion
-- process (Walk.set), kicks with both feet at two ball gaps and two lateral offsets
-- (kick_measure.lua) and moves the mean towards the best. Score per set: the shortest kick plus
-- the mean one, less penalties for a fall or a stance not reached (3 m each), a capture point
-- beyond 5 cm ahead of the support ankle (20 m/m) and a turn over 0.3 rad (2 m/rad): a kick that
-- only just keeps its balance in the sim would not on the robot.
--   ./run_repl Tools/tune/kick_tune.lua GENERATIONS SEED OUT.lua [SPREAD]
-- Prints every set's figures and score; OUT.lua gets the best set (as Walk.set paths) after each
-- generation, OUT_mean.lua the next generation's mean (the more robust choice). KICK_PARAMS=file.lua
-- (such a file) starts from it; SPREAD scales the sampling spread (default 1; smaller to refine).
-- Run by Tools/tune/kick_tune.sh. To keep a result, copy its values into the kick phases of
-- Config/robots/<ROBOT>/walk.lua (kick.leg.5 holds kick.leg.4's targets) and check it with kick_sweep.sh.
-- luacheck: globals Sim Motion wait arg Body
-- kick_measure beside this file; kick_setup and sim_shim with the scenarios they serve (Tests/motion)
local root = os.getenv('HRP_ROOT')
package.path = root .. '/Tools/tune/?.lua;' .. root .. '/Tests/motion/?.lua;' .. package.path
local km = require('kick_measure')
local Walk = require('Walk')

local generations, seed, out = tonumber(arg[1]) or 30, tonumber(arg[2]) or 1, arg[3] or 'kick_best.lua'
local spread = tonumber(arg[4]) or 1
math.randomseed(seed)

-- tuned parameters: walk-config path, sampling spread, bounds
local P = {
  { 'kick.body.2.duration', 0.04, 0.2, 0.8 },
  { 'kick.body.3.duration', 0.04, 0.1, 0.5 },
  { 'kick.body.3.height', 0.008, -0.02, 0.05 },
  { 'kick.body.3.lean', 0.01, -0.09, 0.05 },
  { 'kick.body.3.tilt', 0.05, -0.7, 0.1 },
  { 'kick.body.3.arms', 0.1, 0, 1.2 },
  { 'kick.leg.2.duration', 0.03, 0.05, 0.4 },
  { 'kick.leg.2.z', 0.01, 0.01, 0.08 },
  { 'kick.leg.3.duration', 0.05, 0.1, 0.6 },
  { 'kick.leg.3.x', 0.015, -0.08, 0.04 },
  { 'kick.leg.3.z', 0.012, 0.02, 0.1 },
  { 'kick.leg.3.hip', 0.12, -0.3, 1.2 },
  { 'kick.leg.3.knee', 0.12, 0.3, 2.0 },
  { 'kick.leg.3.ankle', 0.12, -0.5, 1.0 },
  { 'kick.leg.3.arm', 0.1, -0.5, 1.2 },
  { 'kick.leg.4.duration', 0.01, 0.005, 0.1 },
  { 'kick.leg.4.x', 0.015, 0.0, 0.2 },
  { 'kick.leg.4.z', 0.012, 0.0, 0.12 },
  { 'kick.leg.4.hip', 0.12, -2.5, -0.5 },
  { 'kick.leg.4.knee', 0.12, -0.5, 1.0 },
  { 'kick.leg.4.ankle', 0.12, -1.0, 0.6 },
  { 'kick.leg.4.arm', 0.1, -0.5, 1.0 },
  { 'kick.leg.5.duration', 0.03, 0.05, 0.3 },
  -- the ball is met while the leg already heads for the return phase's targets
  { 'kick.leg.6.duration', 0.05, 0.15, 0.6 },
  { 'kick.leg.6.x', 0.015, -0.08, 0.1 },
  { 'kick.leg.6.z', 0.012, 0.0, 0.1 },
  { 'kick.leg.6.hip', 0.1, -1.0, 1.0 },
  { 'kick.leg.6.knee', 0.1, -0.5, 1.5 },
  { 'kick.leg.6.ankle', 0.1, -1.0, 1.0 },
}
-- the kicks of one evaluation: side, gap, lateral; KICK_SET='left:0.08:0,right:0.17:0' replaces them
local KICKS = { { 'left', 0.08, 0 }, { 'right', 0.08, 0 }, { 'left', 0.12, 0 }, { 'right', 0.12, 0 },
  { 'left', 0.1, 0.025 }, { 'right', 0.1, -0.025 } }
if os.getenv('KICK_SET') then
  KICKS = {}
  for side, gap, lat in os.getenv('KICK_SET'):gmatch('(%a+):([%d.]+):([-%d.]+)') do
    KICKS[#KICKS + 1] = { side, tonumber(gap), tonumber(lat) }
  end
  assert(#KICKS > 0, 'KICK_SET: side:gap:lateral,... expected')
end
local POP, ELITE = 10, 4

local function gauss()
  return math.sqrt(-2 * math.log(1 - math.random())) * math.cos(2 * math.pi * math.random())
end

local function apply(x)
  local params = {}
  for i, p in ipairs(P) do params[p[1]] = x[i] end
  km.apply(params, wait)
end

local env = { Sim = Sim, Motion = Motion, wait = wait, Body = Body }
local function evaluate(x)
  apply(x)
  local worst, sum, pen, lines = math.huge, 0, 0, {}
  for _, k in ipairs(KICKS) do
    local f = km.kick(env, k[1], k[2], k[3])
    lines[#lines + 1] = km.describe(k[1], k[2], k[3], f)
    worst, sum = math.min(worst, f.d), sum + f.d
    if f.bad then pen = pen + 3 end
    pen = pen + 20 * math.max(0, f.cp_max - 0.05) + 2 * math.max(0, f.yaw - 0.3)
  end
  return worst + sum / #KICKS - pen, worst, sum / #KICKS, lines
end

local function save(x, what, file)
  local f = assert(io.open(file or out, 'w'))
  f:write(string.format('-- kick_tune seed %d: %s\nreturn {\n', seed, what))
  for i, p in ipairs(P) do f:write(string.format("  ['%s'] = %.4f,\n", p[1], x[i])) end
  f:write('}\n')
  f:close()
end

assert(require('kick_setup').wait_for_motion(wait), 'the motion process is not running')

km.apply_env(wait)   -- start from KICK_PARAMS when given
local mean, sd = {}, {}
for i, p in ipairs(P) do mean[i], sd[i] = Walk.get(p[1]), p[2] * spread end
local best, best_x = -math.huge, nil
for g = 1, generations do
  local pop = {}
  for c = 1, POP do
    local x = {}
    for i, p in ipairs(P) do
      local v = (c == 1) and mean[i] or mean[i] + sd[i] * gauss()
      x[i] = math.max(p[3], math.min(p[4], v))
    end
    local score, worst, avg, lines = evaluate(x)
    pop[c] = { x = x, score = score }
    print(string.format('gen %d set %d: score %.3f (min %.2f, mean %.2f m)%s', g, c, score, worst, avg,
      c == 1 and ' [mean]' or ''))
    for _, l in ipairs(lines) do print('#   ' .. l) end
    io.stdout:flush()
    if score > best then best, best_x = score, x save(x, string.format('score %.3f', score)) end
  end
  table.sort(pop, function(a, b) return a.score > b.score end)
  for i = 1, #P do
    local m, v = 0, 0
    for e = 1, ELITE do m = m + pop[e].x[i] / ELITE end
    for e = 1, ELITE do v = v + (pop[e].x[i] - m) ^ 2 / ELITE end
    mean[i] = m
    sd[i] = math.max(P[i][2] * spread * 0.15, 0.6 * sd[i] + 0.4 * math.sqrt(v))
  end
  print(string.format('gen %d: best %.3f, generation best %.3f', g, best, pop[1].score))
  save(mean, string.format('mean after generation %d (not yet scored)', g), (out:gsub('%.lua$', '')) .. '_mean.lua')
end
if best_x then save(best_x, string.format('score %.3f', best)) end   -- GENERATIONS 0: nothing scored
