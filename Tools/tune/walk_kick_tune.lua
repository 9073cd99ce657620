-- Tunes a walk kick's swing in the sim (lockstep, the motion process alone): a cross-entropy search
-- over the wind-up's and the strike's way-points and joint offsets (walkKick.<kind>.phases 2 to 4,
-- set live through Walk.set), scored by the ball's travel over ball positions in the kick zone,
-- penalised for a fall or a stop:
--   Tests/motion/kick_sim.sh-run: ./run_repl Tools/tune/walk_kick_tune.lua KIND ITERS POP [OUT.lua]
-- (Tools/tune/walk_kick_tune.sh). Prints each set's figures; OUT.lua gets the best set found.
-- luacheck: globals Sim Motion Walk wait arg Body
package.path = os.getenv('HRP_ROOT') .. '/Tests/motion/?.lua;' .. package.path
local ks = require('kick_setup')
local Config = require('Config')

local kind, iters, pop, out = arg[1] or 'forward', tonumber(arg[2] or '6'), tonumber(arg[3] or '10'), arg[4]
local p = Config.load('walk')
local motion = assert(ks.wait_for_motion(wait), 'the motion process is not running')
local cfg = p.walkKick[kind]
local along = kind == 'forward' and 'x' or 'y'  -- the strike's direction

-- the searched parameters: key path under walkKick.<kind>, range
local P = {
  { 'phases.2.duration', 0.1, 0.25 },
  { 'phases.2.z', 0.03, 0.09 },
  { 'phases.2.hip', -0.2, 0.8 },
  { 'phases.2.knee', 0.0, 1.5 },
  { 'phases.2.ankle', -0.6, 0.4 },
  { 'phases.3.' .. along, -0.05, 0.2 },
  { 'phases.3.z', 0.0, 0.1 },
  { 'phases.3.hip', -2.0, 0.0 },
  { 'phases.3.knee', -0.9, 0.3 },
  { 'phases.3.ankle', -0.7, 1.2 },
  { 'phases.3.tilt', -0.5, 0.0 },
  { 'phases.3.arms', 0.0, 0.5 },
  { 'phases.3.duration', 0.02, 0.08 },
  { 'phases.4.duration', 0.01, 0.15 },
  { 'phases.5.duration', 0.06, 0.2 },
  { 'support.x', -0.02, 0.03 },
  { 'support.y', -0.01, 0.02 },
  -- how far behind and ahead of the support ankle the kicking ankle may go (wind-up, strike target)
  { 'reach.x.1', -0.14, -0.02 },
  { 'reach.x.2', 0.10, 0.22 },
  -- where the kicking ankle is, behind the ball's centre, when the foot meets it
  { 'contact.x', 0.08, 0.18 },
  -- a ball further ahead at the kick step's start waits for the next step
  { 'ballMax', 0.12, 0.17 },
}
if kind == 'side' then
  P[4], P[9] = { 'phases.2.hipRoll', -0.4, 0.1 }, { 'phases.3.hipRoll', 0.0, 0.6 }
  -- the side kick meets the ball beside the support foot, not ahead of it
  for i, d in ipairs(P) do
    if d[1] == 'contact.x' then P[i] = { 'contact.x', -0.04, 0.06 } end
    if d[1] == 'ballMax' then P[i] = { 'ballMax', 0.0, 0.1 } end
  end
end

-- the config's value at path, nil where the kind's config has none (a side kick's phase without a hip)
local function get(path)
  local t = cfg
  for part in path:gmatch('[^%.]+') do
    if type(t) ~= 'table' then return nil end
    t = rawget(t, tonumber(part) or part)
  end
  return t
end

local function set(path, v)
  for _ = 1, 50 do
    local ok = Walk.set('walkKick.' .. kind .. '.' .. path, v)
    if ok then return end
    wait(0.01)
  end
  error('Walk.set did not land: ' .. path)
end

-- phase 4 holds phase 3's targets; the step lasts the phases plus 0.06 s of landing
local function apply(x)
  local dur = {}
  for i, ph in ipairs(cfg.phases) do dur[i] = ph.duration end
  for i, d in ipairs(P) do
    set(d[1], x[i])
    local n, key = d[1]:match('^phases%.(%d)%.(.+)$')
    if n == '3' and key ~= 'duration' then set('phases.4.' .. key, x[i]) end
    if key == 'duration' then dur[tonumber(n)] = x[i] end
  end
  local sum = 0
  for _, v in ipairs(dur) do sum = sum + v end
  set('tStep', (sum + 0.06) / (cfg.phSingle[2] - cfg.phSingle[1]))
end

local function case(foot, dx, dy)
  ks.walk_steady(Sim, Motion, Walk, wait, 0.12)
  local falls0 = Motion.falls()
  local b = cfg.ball
  local sgn = foot == 'left' and 1 or -1
  local bx, by = b.x + dx, sgn * (p.footY + b.y + dy)
  local r = Sim.truth()
  local c, s = math.cos(r.yaw), math.sin(r.yaw)
  Sim.teleport_ball(r.x + c * bx - s * by, r.y + s * bx + c * by)
  wait(0.01)
  local b0 = Sim.truth().ball
  Walk.kick(kind, foot, bx, by)
  local t0 = Body.get_time()
  local d = 0
  while Body.get_time() - t0 < 7 do
    wait(0.05)
    r = Sim.truth()
    d = math.sqrt((r.ball.x - b0.x) ^ 2 + (r.ball.y - b0.y) ^ 2)
    if Body.get_time() - t0 > 1.5 and r.ball.vx ^ 2 + r.ball.vy ^ 2 < 0.02 ^ 2 then break end
    if r.fallen then break end
  end
  local fell = Motion.falls() > falls0 or r.fallen
  return math.min(d, 3.0), fell, motion.walking[0] == 1
end

-- the forward kick's cases span the kick zone (both feet, the ball -0.06 to +0.06 m along and
-- +-0.02 m across its nominal spot): its goal is every case's distance, so the score weighs the
-- shortest as much as the mean
local CASES = kind == 'forward' and { { 'left', -0.06, -0.02 }, { 'left', -0.02, 0.02 }, { 'left', 0.02, -0.02 },
  { 'left', 0.06, 0.02 }, { 'right', -0.06, 0.02 }, { 'right', -0.02, -0.02 }, { 'right', 0.02, 0.02 },
  { 'right', 0.06, -0.02 } }
  or { { 'left', -0.03, 0 }, { 'left', 0.03, 0.02 }, { 'left', 0, -0.02 }, { 'right', -0.03, 0.02 },
    { 'right', 0.03, 0 }, { 'right', 0, -0.02 } }

local function score(x)
  apply(x)
  local total, least, txt = 0, math.huge, {}
  for _, cs in ipairs(CASES) do
    local d, fell, walking = case(cs[1], cs[2], cs[3])
    local v = d - (fell and 3 or 0) - (walking and 0 or 1)
    total, least = total + v, math.min(least, v)
    txt[#txt + 1] = string.format('%.2f%s', d, fell and 'F' or (walking and '' or 'S'))
  end
  return 0.5 * total / #CASES + 0.5 * least, table.concat(txt, ' ')
end

-- cross-entropy search from the config's values
local mean, sd = {}, {}
for i, d in ipairs(P) do
  mean[i] = get(d[1]) or 0.5 * (d[2] + d[3])
  sd[i] = (d[3] - d[2]) / 4
end
local seed = 12345
local function rnd()
  seed = (seed * 1103515245 + 12345) % 2147483648
  return seed / 2147483648
end
local function gauss() return math.sqrt(-2 * math.log(1 - rnd())) * math.cos(2 * math.pi * rnd()) end
local best, bestx = -math.huge, nil
local function fmt(x)
  local t = {}
  for i, d in ipairs(P) do t[#t + 1] = string.format('%s=%.3f', d[1], x[i]) end
  return table.concat(t, ' ')
end
for it = 1, iters do
  local scored = {}
  for k = 1, pop do
    local x = {}
    for i, d in ipairs(P) do
      x[i] = (it == 1 and k == 1) and mean[i] or math.max(d[2], math.min(d[3], mean[i] + sd[i] * gauss()))
    end
    local f, txt = score(x)
    scored[#scored + 1] = { f = f, x = x }
    print(string.format('iter %d set %d: %.3f  [%s]', it, k, f, txt))
    io.stdout:flush()
    if f > best then
      best, bestx = f, x
      print('best ' .. fmt(x))
      if out then
        local fh = io.open(out, 'w')
        for i, d in ipairs(P) do fh:write(string.format('%s = %.4f\n', d[1], x[i])) end
        fh:write(string.format('-- score %.3f\n', f))
        fh:close()
      end
    end
  end
  table.sort(scored, function(a, b) return a.f > b.f end)
  local ne = math.max(2, math.floor(pop / 3))
  for i = 1, #P do
    local m, v = 0, 0
    for e = 1, ne do m = m + scored[e].x[i] end
    m = m / ne
    for e = 1, ne do v = v + (scored[e].x[i] - m) ^ 2 end
    mean[i], sd[i] = m, math.max(math.sqrt(v / ne), (P[i][3] - P[i][2]) / 40)
  end
end
if bestx then print(string.format('best %.3f: %s', best, fmt(bestx))) end   -- ITERS 0: nothing scored
