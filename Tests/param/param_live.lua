-- Live parameters in the running robot (Tests/param/param_live_test.sh, sim in lockstep, motion and
-- vision running): the walk's step time changed from the REPL changes the step period measured from
-- the feet (the sim's sole contact forces); a vision threshold changed live stops and restarts the
-- ball's detection; param.save() writes the step time into the site overlay. Prints TAP.
-- luacheck: globals Sim Motion Walk wait Body param
local n, fails = 0, 0
local function tap(ok, msg)
  n = n + 1
  if not ok then fails = fails + 1 end
  print(string.format('%s %d - %s', ok and 'ok' or 'not ok', n, msg))
  io.stdout:flush()
end

local motion = require('shm').open('motion')
for _ = 1, 300 do
  if motion.tick[0] ~= 0 and Body.get_tick() - motion.tick[0] <= 2 then break end
  wait(0.1)
end
tap(motion.tick[0] ~= 0, 'the motion process runs')

-- Step period from the feet: the times the left sole leaves the ground (its contact force falls
-- below 15% of the two soles' total after having carried more than 40%) over `seconds` of walking;
-- returns the mean interval between lift-offs / 2 (one step per foot) and the count.
local function step_period(seconds)
  local period = Body.period()
  local lifts, on = {}, false
  for _ = 1, math.floor(seconds / period) do
    wait(period)
    local f = Body.get_foot_force()
    local total = f[1] + f[2]
    if total > 1 then
      if f[1] > 0.4 * total then on = true
      elseif on and f[1] < 0.15 * total then
        on = false
        lifts[#lifts + 1] = Body.get_time()
      end
    end
  end
  if #lifts < 3 then return nil, #lifts end
  return (lifts[#lifts] - lifts[1]) / (#lifts - 1) / 2, #lifts
end

-- ---- the walk's step time
local t0 = param('walk.tStep')
Motion.request('walk')
Walk.set_velocity(0.08, 0, 0)
wait(2)
local p0, k0 = step_period(4)
print(string.format('# walk.tStep %.3f s: step period from the feet %s s (%d lift-offs)', t0, tostring(p0), k0))
tap(p0 and math.abs(p0 - t0) < 0.05 * t0, 'the step period measured from the feet is walk.tStep')

local t1 = 0.32
param('walk.tStep', t1)
tap(param('walk.tStep') == t1, 'param() reads the new value at once')
wait(1.5)
local applied = false
for _, p in ipairs(param.status()) do
  if p.name == 'motion' and p.alive and p.applied then applied = true end
end
tap(applied, 'the motion process reports the change applied (param.status)')
local p1, k1 = step_period(4)
print(string.format('# walk.tStep %.3f s: step period from the feet %s s (%d lift-offs)', t1, tostring(p1), k1))
tap(p1 and math.abs(p1 - t1) < 0.05 * t1, string.format('after param(\'walk.tStep\', %.2f) the feet step at %s s', t1,
  p1 and string.format('%.3f', p1) or '?'))
tap(not Sim.truth().fallen and Motion.falls() == 0, 'the robot walked on without a fall through the change')

-- bad input: refused with the key named, nothing sent
local ok, err = pcall(param, 'walk.tStepp', 0.3)
tap(not ok and err:find("unknown key 'walk.tStepp'", 1, true) ~= nil, 'an unknown key is refused naming it')
ok, err = pcall(param, 'walk.tStep', 0 / 0)
tap(not ok and err:find('finite', 1, true) ~= nil and param('walk.tStep') == t1, 'NaN is refused')
ok, err = pcall(param, 'walk.tStep', 'fast')
tap(not ok and err:find('is a number', 1, true) ~= nil, 'a value of another type is refused')

-- ---- saving: the highest layer that sets walk.tStep is the test's site overlay
local files = param.save()
print('# saved: ' .. tostring(files['walk.tStep']))
tap(files['walk.tStep'] and files['walk.tStep']:find('/walk.lua$') ~= nil and files['walk.tStep']:find('^/') ~= nil,
  'param.save() writes walk.tStep into the site overlay that sets it (' .. tostring(files['walk.tStep']) .. ')')

Walk.set_velocity(0, 0, 0)
Motion.request('stand')
wait(2)

-- ---- a vision threshold: the ball 1.5 m ahead is seen, then not beyond a 0.5 m range, then again
local tr = Sim.truth()
Sim.teleport_ball(tr.x + 1.5 * math.cos(tr.yaw), tr.y + 1.5 * math.sin(tr.yaw))
local vision = require('shm').open('vision')
local function detections(seconds)
  local frames, seen, last = 0, 0, vision.frame[0]
  for _ = 1, math.floor(seconds / 0.05) do
    wait(0.05)
    if vision.frame[0] ~= last then
      last = vision.frame[0]
      frames = frames + 1
      if vision.ball_detected[0] == 1 then seen = seen + 1 end
    end
  end
  return seen, frames
end
wait(1)
local s0, f0 = detections(1.5)
local range = param('vision.ball.max_range')
param('vision.ball.max_range', 0.5)
wait(0.3)
local s1, f1 = detections(1.5)
param('vision.ball.max_range', range)
wait(0.3)
local s2, f2 = detections(1.5)
print(string.format('# ball 1.5 m ahead seen in %d/%d frames; max_range 0.5: %d/%d; back to %.1f: %d/%d', s0, f0,
  s1, f1, range, s2, f2))
tap(f0 > 5 and s0 >= 0.8 * f0, 'vision sees the ball 1.5 m ahead')
tap(f1 > 5 and s1 == 0, "after param('vision.ball.max_range', 0.5) the running vision process refuses it")
tap(f2 > 5 and s2 >= 0.8 * f2, 'set back live, the ball is seen again')

print('1..' .. n)
if fails > 0 then error(fails .. ' of ' .. n .. ' failed', 0) end
