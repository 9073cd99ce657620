-- The balance feedback on the ankle F/T sensors (Player/Motion/balance.lua) measured in the sim's
-- lockstep, off and on in the same run (Walk.set('balance.zmpGain'/'balance.walkGain', { 0, 0 }) off,
-- the body's walk config for on), each case from a reset robot:
--   ./run_repl Tests/motion/balance_scenarios.lua zmp    -- ZMP error (the feet's measured ZMP minus
--       the walk's reference, motion.zmp, every 0.01 s) standing, standing leaned on by a steady
--       push, walking, walking against a steady push; TAP: no falls, and the feedback reduces the
--       error where the plan is wrong for a while (the steady push; undisturbed, standing the error
--       is the contacts' chatter about a mean of 2 mm, walking the step's own ZMP swing: figures)
--   ./run_repl Tests/motion/balance_scenarios.lua push   -- the largest short push (N for 0.1 s,
--       forwards at the torso) survived standing and walking (at four moments of a step), off and on
--       (figures, no pass/fail)
-- Prints TAP lines and "# " figures.
-- luacheck: globals Sim Motion Walk wait Body
local shm = require('shm')
local Config = require('Config')
local name = arg[1] or 'zmp'
local scenario_lib = require('Tests.scenario_lib')
local sc, bisect = scenario_lib.new(wait, Body), scenario_lib.bisect
local ks = require('Tests.motion.kick_setup')
local tap, note, wait_until = sc.tap, sc.note, sc.wait_until

local motion = shm.open('motion')
if not wait_until(function() return motion.tick[0] ~= 0 end, 30) then
  tap(false, 'the motion process is not running')
  os.exit(1)
end

local cfg = Config.load('walk').balance
-- (copies: Walk.set changes this process's config table too)
local GAINS = { off = { { 0, 0 }, { 0, 0 } },
  on = { { cfg.zmpGain[1], cfg.zmpGain[2] }, { cfg.walkGain[1], cfg.walkGain[2] } } }
if cfg.zmpGain[1] <= 0 then
  tap(false, 'the walk config of ' .. Config.robot() .. ' has the balance feedback off (balance.zmpGain = { 0, 0 })')
  os.exit(1)
end
local function set(key, v) while not Walk.set(key, v) do wait(0.01) end end
local function feedback(mode)
  set('balance.zmpGain', GAINS[mode][1])
  set('balance.walkGain', GAINS[mode][2])
end

-- a reset robot standing (VX nil) or walking forward at VX for 2 s, pushed (on the torso, along its
-- heading, N) for the rest of the case when PUSH is given
local function start(vx, push)
  -- stopped first: a reset in mid-step puts the robot down on one foot with the walk going on
  Walk.set_velocity(0, 0, 0)
  Motion.request('stand')
  wait_until(function() return Motion.state() == 'stance' or Motion.state() == 'falling' end, 10)
  Sim.reset()
  wait(0.2)
  Motion.request('stand')
  wait_until(function() return Motion.state() == 'stance' end, 10)
  wait(2)
  if vx then
    Motion.request('walk')
    Walk.set_velocity(vx, 0, 0)
    wait(2)
  end
  if push then
    local a = Sim.truth()
    Sim.push(push * math.cos(a.yaw), push * math.sin(a.yaw), 60)
    wait(8) -- the feedback's time to act (its shift moves 4 mm/s at most) and the robot's to lean
  end
end

-- ZMP error over SECS: RMS along x and y, mean along x (the robot's heading is the walk frame's x
-- after a reset), and whether the robot fell
local function zmp_error(secs)
  local n, sx, sy, mx = 0, 0, 0, 0
  local t0 = Body.get_time()
  local fell = false
  while Body.get_time() - t0 < secs do
    wait(0.01)
    if motion.zmp_contact[0] == 1 then
      local ex, ey = motion.zmp[0] - motion.zmp[2], motion.zmp[1] - motion.zmp[3]
      n, sx, sy, mx = n + 1, sx + ex * ex, sy + ey * ey, mx + ex
    end
    if Sim.truth().fallen then fell = true break end
  end
  n = math.max(n, 1)
  return { x = math.sqrt(sx / n), y = math.sqrt(sy / n), mean = mx / n, fell = fell }
end

local function scenario_zmp()
  local cases = {
    { 'standing', nil, nil, 6 },
    { 'standing, pushed 30 N forwards', nil, 30, 4 },
    { 'walking 0.25 m/s', 0.25, nil, 8 },
    { 'walking 0.2 m/s, pushed 20 N forwards', 0.2, 20, 8 },
  }
  local res = {}
  -- the first stance after the process starts rocks sideways for a few seconds (either setting):
  -- once, before the cases
  start()
  for k, c in ipairs(cases) do
    res[k] = {}
    for _, mode in ipairs({ 'off', 'on' }) do
      feedback(mode)
      start(c[2], c[3])
      local e = zmp_error(c[4])
      res[k][mode] = e
      note('%-40s feedback %-3s: ZMP error RMS x %.1f mm, y %.1f mm; mean x %+.1f mm; COM shift (%.1f, %.1f) mm%s',
        c[1], mode, 1000 * e.x, 1000 * e.y, 1000 * e.mean, 1000 * motion.zmp[4], 1000 * motion.zmp[5],
        e.fell and '; FELL' or '')
      tap(not e.fell, string.format('%s, feedback %s: no fall', c[1], mode))
    end
  end
  Sim.push(0, 0, 0)
  local p = res[2]
  tap(p.on.x < 0.6 * p.off.x, string.format('standing pushed: the feedback cuts the ZMP error RMS along the push '
    .. 'below 60%% (%.1f -> %.1f mm)', 1000 * p.off.x, 1000 * p.on.x))
  local w = res[4]
  tap(math.abs(w.on.mean) < 0.6 * math.abs(w.off.mean), string.format('walking pushed: the feedback cuts the '
    .. 'mean ZMP error along the push below 60%% (%+.1f -> %+.1f mm)', 1000 * w.off.mean, 1000 * w.on.mean))
end

-- largest forward push (N for 0.1 s) survived: bisection, each trial from a reset robot
local function scenario_push()
  for _, c in ipairs({ { 'standing', nil, 400 }, { 'walking 0.2 m/s', 0.2, 400 } }) do
    for _, mode in ipairs({ 'off', 'on' }) do
      feedback(mode)
      local lo, hi = 0, c[3]
      -- walking, survived only if survived at four moments of a step (0.125 s apart)
      local function survives(f)
        for k = 0, c[2] and 3 or 0 do
          start(c[2])
          wait(0.5 + 0.125 * k)
          if ks.push_falls(Sim, Motion, wait_until, 'forward', f) then return false end
        end
        return true
      end
      lo, hi = bisect(lo, hi, 6, survives)
      note('%-16s feedback %-3s: largest forward push survived %.0f N x 0.1 s = %.1f N s (fell at %.0f N)',
        c[1], mode, lo, 0.1 * lo, hi)
    end
  end
end

if name == 'zmp' then scenario_zmp()
elseif name == 'push' then scenario_push()
else tap(false, 'balance_scenarios: unknown scenario ' .. tostring(name)) end
Walk.set_velocity(0, 0, 0)
Motion.request('stand')
