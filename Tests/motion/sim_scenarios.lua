-- Walking scenarios in the sim's lockstep, run by ./run_repl (see sim_walk_test.sh):
--   ./run_repl Tests/motion/sim_scenarios.lua NAME [ARGS...]
-- NAME: forward, sideways, turn, backward, random, push, fallpolicy, keypose, kick, head, pushmax,
-- speed, ramp. Prints TAP lines ("ok N - ..." / "not ok N - ...") and "# " figures; measured from the
-- sim's truth (Sim.truth()).
-- luacheck: globals Sim Motion Walk wait arg shm Body
local name = arg[1]
local scenario_lib = require('Tests.scenario_lib')
local sc = scenario_lib.new(wait, Body)
local tap, note, wait_until = sc.tap, sc.note, sc.wait_until
local function wrap(a) return (a + math.pi) % (2 * math.pi) - math.pi end
local deg = 180 / math.pi

-- until Lib/Sim.lua exists: the same calls straight over the sim block
-- luacheck: ignore Sim
if not Sim then
  package.path = os.getenv('HRP_ROOT') .. '/Tests/motion/?.lua;' .. package.path
  Sim = require('sim_shim')
end
if not Sim or not Motion or not Walk then
  tap(false, 'scenario ' .. tostring(name) .. ': Sim, Motion or Walk API missing')
  os.exit(1)
end

package.path = os.getenv('HRP_ROOT') .. '/Tests/motion/?.lua;' .. package.path
local ks = require('kick_setup')
local motion = ks.need_motion(wait, tap)

-- WALK_PARAMS changes walk parameters first (e.g. to switch feedback off)
ks.apply_walk_params(Walk, wait, note)

local function stand(timeout)
  Walk.set_velocity(0, 0, 0)
  Motion.request('stand')
  local ok = wait_until(function() return Motion.state() == 'stance' end, timeout or 10)
  wait(1.5)
  return ok
end

-- walks at (vx, vy, va) for `seconds` after `ramp` seconds; returns the measured velocity in the
-- robot's start frame (m/s, m/s, rad/s), whether it fell, and the truth at start and end
local function walk_for(vx, vy, va, seconds, ramp)
  Motion.request('walk')
  Walk.set_velocity(vx, vy, va)
  wait(ramp or 2)
  local a = Sim.truth()
  local fell = false
  local yaw, last = 0, a.yaw
  local t0 = Body.get_time()
  while Body.get_time() - t0 < seconds do
    wait(0.1)
    local s = Sim.truth()
    yaw = yaw + wrap(s.yaw - last)
    last = s.yaw
    if s.fallen or Motion.state() ~= 'walk' then fell = true break end
  end
  local b = Sim.truth()
  local dt = Body.get_time() - t0
  local c, s = math.cos(a.yaw), math.sin(a.yaw)
  local dx, dy = b.x - a.x, b.y - a.y
  return { (c * dx + s * dy) / dt, (-s * dx + c * dy) / dt, yaw / dt }, fell, a, b, yaw
end

-- a fresh world; the robot placed at (x, y, yaw) (default: a field corner, facing along the
-- diagonal: 10 m of free carpet), the ball out of the way
local function start_clean(x, y, yaw)
  -- a walking robot stops first: put back into the world mid-step, a heavy body on weak drives (the
  -- HOAP-3) falls, and one without stand-ups stays down for the next run
  if Motion.state() == 'walk' then stand(5) end
  Sim.reset()
  wait(0.2)
  Sim.teleport_robot(x or -4.3, y or -3.3, yaw or math.atan2(6.6, 8.6))
  Sim.teleport_ball(4.0, -3.5)
  wait(0.2)
  return stand()
end

local scenarios = {}

-- this body's targets (Tests/motion/targets.lua)
local robot_name = require('Config').robot()
local targets = require('targets')[robot_name]
if not targets then
  tap(false, 'no walking targets for robot ' .. robot_name .. ' in Tests/motion/targets.lua')
  os.exit(1)
end

-- a walk along one axis of targets.lua: its goal, the command (speed, or the goal's) and a fresh start
local function start_axis(axis, speed)
  local goal = targets[axis]
  start_clean()
  return goal, tonumber(speed) or goal.command
end

function scenarios.forward(speed)
  local goal, v = start_axis('forward', speed)
  local t0 = Sim.truth()
  local vel, fell, _, _, yaw = walk_for(v, 0, 0, 30, 3)
  note('forward: commanded %.2f m/s, measured %.3f m/s over 30 s, sideways %.3f m/s, heading drift %.1f deg',
    v, vel[1], vel[2], yaw * deg)
  tap(not fell, 'forward walk: no fall in 30 s')
  tap(vel[1] >= goal.least, string.format('forward walk at >= %.2f m/s (measured %.3f)', goal.least, vel[1]))
  tap(math.abs(yaw) * deg < 10, string.format('heading drift below 10 deg (%.1f)', yaw * deg))
  -- stop into stance: the walk finishes its step and the torso comes to rest
  Walk.set_velocity(0, 0, 0)
  Motion.request('stand')
  local stopped = wait_until(function() return Motion.state() == 'stance' end, 3)
  wait(1.0)
  local a = Sim.truth()
  wait(1.0)
  local b = Sim.truth()
  local still = math.sqrt((b.x - a.x) ^ 2 + (b.y - a.y) ^ 2)
  tap(stopped and not b.fallen and still < 0.005,
    string.format('stops into stance within 3 s and stands still (moved %.4f m in 1 s)', still))
  note('start to stop: %.2f m', math.sqrt((b.x - t0.x) ^ 2 + (b.y - t0.y) ^ 2))
end

-- stands still in stance for `seconds` (default 60): no fall, the torso stays put
function scenarios.stand(seconds)
  seconds = tonumber(seconds) or 60
  start_clean()
  local a = Sim.truth()
  local falls0 = Motion.falls()
  local fell = wait_until(function() return Sim.truth().fallen or Motion.falls() > falls0 end, seconds)
  local b = Sim.truth()
  local moved = math.sqrt((b.x - a.x) ^ 2 + (b.y - a.y) ^ 2)
  note('stand: %.0f s in stance, the torso moved %.4f m, pitch %.3f rad', seconds, moved, b.pitch)
  tap(not fell and not b.fallen and Motion.state() == 'stance',
    string.format('stands %.0f s without a fall', seconds))
  tap(moved < 0.01, string.format('stands still (the torso moved %.4f m)', moved))
end

-- (commands a little above the goal speeds: the feet slip a little on the carpet)
function scenarios.sideways(speed)
  local goal, v = start_axis('sideways', speed)
  local vel, fell = walk_for(0, v, 0, 15, 2)
  note('sideways: commanded %.3f m/s, measured %.3f m/s (forward %.3f)', v, vel[2], vel[1])
  tap(not fell and vel[2] >= goal.least,
    string.format('sideways %.2f m/s for 15 s (measured %.3f)', goal.least, vel[2]))
  vel, fell = walk_for(0, -v, 0, 8, 2)
  tap(not fell and vel[2] <= -goal.least, string.format('sideways right %.2f m/s (measured %.3f)', goal.least, vel[2]))
  tap(stand(5) and not Sim.truth().fallen, 'stops into stance')
end

function scenarios.turn(speed)
  local goal, v = start_axis('turn', speed)
  local a0 = Sim.truth()
  local vel, fell, _, b = walk_for(0, 0, v, 10, 2)
  local drift = math.sqrt((b.x - a0.x) ^ 2 + (b.y - a0.y) ^ 2)
  note('turn: commanded %.2f rad/s, measured %.3f rad/s, position drift %.2f m', v, vel[3], drift)
  tap(not fell and vel[3] >= goal.least,
    string.format('turning on the spot at %.1f rad/s (measured %.3f)', goal.least, vel[3]))
  vel, fell = walk_for(0, 0, -v, 6, 2)
  tap(not fell and vel[3] <= -goal.least,
    string.format('turning right at %.1f rad/s (measured %.3f)', goal.least, vel[3]))
  tap(stand(5) and not Sim.truth().fallen, 'stops into stance')
end

function scenarios.backward(speed)
  local goal, v = start_axis('backward', speed)
  local vel, fell = walk_for(-v, 0, 0, 15, 2)
  note('backward: commanded %.3f m/s, measured %.3f m/s', -v, vel[1])
  tap(not fell and vel[1] <= -goal.least,
    string.format('backwards %.2f m/s for 15 s (measured %.3f)', goal.least, vel[1]))
  tap(stand(5) and not Sim.truth().fallen, 'stops into stance')
end

function scenarios.random(seconds, seed)
  seconds = tonumber(seconds) or 60
  local s = (tonumber(seed) or 1) * 7919 + 11
  local function rnd()
    s = (s * 1103515245 + 12345) % 2147483648
    return s / 2147483648
  end
  local stood = start_clean()
  local s0 = Sim.truth()
  if not stood or s0.fallen then
    note('random: the start did not stand: state %s, fallen %s, roll %.2f pitch %.2f', Motion.state(),
      tostring(s0.fallen), s0.roll, s0.pitch)
  end
  Motion.request('walk')
  local lim = { Walk.get('velLimitX'), Walk.get('velLimitY'), Walk.get('velLimitA') }
  local falls0 = Motion.falls()
  local t0 = Body.get_time()
  local fell, changes = false, 0
  local last
  while Body.get_time() - t0 < seconds and not fell do
    local v = {}
    for k = 1, 3 do v[k] = lim[k][1] + rnd() * (lim[k][2] - lim[k][1]) end
    local cx, cy, ca = Walk.set_velocity(v[1], v[2], v[3])
    changes = changes + 1
    last = string.format('t=%.1f command %.3f %.3f %.3f', Body.get_time() - t0, cx, cy, ca)
    if os.getenv('VERBOSE') then note('%s', last) end
    local hold = 1 + 3 * rnd()
    local t1 = Body.get_time()
    while Body.get_time() - t1 < hold do
      wait(0.1)
      local now = Sim.truth()
      if now.fallen or Motion.falls() > falls0 then
        fell = true
        note('random: down at t=%.1f (%s): truth fallen %s, roll %.2f pitch %.2f, falls %d -> %d, state %s',
          Body.get_time() - t0, last, tostring(now.fallen), now.roll, now.pitch, falls0, Motion.falls(), Motion.state())
        break
      end
    end
  end
  note('random: %d commands in %.0f s', changes, Body.get_time() - t0)
  tap(not fell, string.format('%.0f s of random velocity commands without a fall', seconds))
end

-- from a fresh start, walks at 0.1 m/s for `seconds`, pushes the robot along its heading with f N
-- (backwards when f < 0) for 0.2 s and watches up to 4 s: the fall count before the push, the robot
-- time of the push, of the fall (the sim's truth) and of its detection (the motion process), nil
-- where none came
local function push_down(seconds, f)
  start_clean()
  Motion.request('walk')
  Walk.set_velocity(0.1, 0, 0)
  wait(seconds)
  local falls0 = Motion.falls()
  local a = Sim.truth()
  Sim.push(f * math.cos(a.yaw), f * math.sin(a.yaw), 0.2)
  local t_push, t_fallen, t_detect = Body.get_time(), nil, nil
  wait_until(function()
    if not t_fallen and Sim.truth().fallen then t_fallen = Body.get_time() end
    if not t_detect and Motion.falls() > falls0 then t_detect = motion.fall_time[0] end
    return t_fallen and t_detect
  end, 4)
  return falls0, t_push, t_fallen, t_detect
end

-- pushes the walking robot over (fx along its heading) and follows the recovery
local function push_over(dir)
  -- 25 N for 0.2 s: over it goes, without a somersault
  local falls0, t_push, t_fallen, t_detect = push_down(3, 25 * dir)
  local what = dir > 0 and 'forwards' or 'backwards'
  if not t_fallen then
    tap(false, 'pushed ' .. what .. ': the robot did not fall (push too weak)')
    return
  end
  local lag = t_detect and (t_detect - t_fallen) or math.huge
  note('pushed %s: fallen (truth) %.2f s after the push; detected %.2f s after the push (%.2f s after truth)',
    what, t_fallen - t_push, (t_detect or math.huge) - t_push, lag)
  tap(t_detect ~= nil and lag <= 0.3, string.format('pushed %s: fall detected within 0.3 s (%.2f s)', what, lag))
  local up = wait_until(function() return Motion.state() == 'walk' and not Sim.truth().fallen end, 25)
  note('pushed %s: state %s, falls %d', what, Motion.state(), Motion.falls() - falls0)
  tap(up, string.format('pushed %s: stands up by itself (%d falls counted)', what, Motion.falls() - falls0))
  local b = Sim.truth()
  wait(4)
  local c = Sim.truth()
  local d = math.sqrt((c.x - b.x) ^ 2 + (c.y - b.y) ^ 2)
  tap(up and not c.fallen and d > 0.15, string.format('pushed %s: walks again (%.2f m in 4 s)', what, d))
end

function scenarios.push()
  push_over(1)
  push_over(-1)
end

-- a body with a fall policy (walk config fallPolicy: too heavy to go limp or to get up by itself):
-- pushed over while walking, forwards and backwards (`force` N, default 250, for 0.2 s along its heading), the
-- fall is detected, the protective pose is taken and held at the policy's hardness (no joint goes
-- limp), no stand-up is tried; lying, it stays in falling
local function push_policy(dir, force)
  local policy = Walk.get('fallPolicy')
  if not policy then
    tap(false, 'fallpolicy: the walk config of ' .. robot_name .. ' has no fallPolicy')
    return
  end
  local falls0, t_push, t_fallen, t_detect = push_down(4, force * dir)
  local what = dir > 0 and 'forwards' or 'backwards'
  if not t_fallen then
    tap(false, string.format('pushed %s (%.0f N for 0.2 s): the robot did not fall (push too weak)', what, force))
    return
  end
  local lag = t_detect and (t_detect - t_fallen) or math.huge
  note('pushed %s (%.0f N for 0.2 s): fallen (truth) %.2f s after the push; detected %.2f s after truth',
    what, force, t_fallen - t_push, lag)
  tap(t_detect ~= nil and lag <= 0.3, string.format('pushed %s: fall detected within 0.3 s (%.2f s)', what, lag))
  wait(6)
  local softest, worst, worst_joint = 1, 0, ''
  for _, jn in ipairs(Body.joint_names()) do
    softest = math.min(softest, Body.get_hardness(jn))
    local want = rawget(policy.pose, jn)
    if want and Body.get_hardness(jn) > 0 then
      local e = math.abs(Body.get_position(jn) - Body.get_command(jn))
      if e > worst then worst, worst_joint = e, jn end
    end
  end
  note('pushed %s: 6 s later state %s, falls %d, least hardness %.2f, the pose held within %.4f rad (%s)',
    what, Motion.state(), Motion.falls() - falls0, softest, worst, worst_joint)
  tap(Motion.state() == 'falling' and Motion.falls() - falls0 == 1,
    string.format('pushed %s: stays in falling, no stand-up tried (state %s)', what, Motion.state()))
  local hold = policy.rest == 'hold'
  tap(hold and softest >= policy.hardness - 1e-9 or not hold and softest == 0,
    string.format('pushed %s: the servos %s (least hardness %.2f)', what, hold and 'hold the protective pose'
      or 'are released', softest))
end

-- key poses for the arms and the waist (Config/robots/<ROBOT>/keyframes/<name>.lua, default 'wave')
-- played by a caller through Body commands (Lib/keypose.lua) while the robot stands: no fall, the
-- feet stay put, the joints follow, and they are the motion's again afterwards
function scenarios.keypose(file)
  file = file or 'wave'
  local keypose = require('keypose')
  start_clean()
  local kf, duration = keypose.load(file)
  local a = Sim.truth()
  local falls0 = Motion.falls()
  local lag = keypose.play(file, wait)
  wait(1)
  local b = Sim.truth()
  local moved = math.sqrt((b.x - a.x) ^ 2 + (b.y - a.y) ^ 2)
  note('keypose %s: %d joints, %.1f s; largest tracking lag %.3f rad; the torso moved %.4f m, state %s',
    file, #kf.joints, duration, lag, moved, Motion.state())
  tap(not b.fallen and Motion.falls() == falls0 and Motion.state() == 'stance',
    string.format('key poses %s (%.1f s) played while standing, no fall', file, duration))
  tap(moved < 0.02, string.format('the feet stay put (the torso moved %.4f m)', moved))
  tap(lag < 0.3, string.format('the joints follow the key poses (largest lag %.3f rad)', lag))
  local taken = false
  for _, j in ipairs(Body.joint_names()) do taken = taken or Body.taken(j) end
  tap(not taken, 'every joint is given back at the end')
end

function scenarios.fallpolicy(force)
  force = tonumber(force) or 250
  push_policy(1, force)
  push_policy(-1, force)
end

-- kick: the ball's centre `gap` m (default 0.1) ahead of the kicking foot's toe, in line with the
-- sole's centre (placed from the measured leg angles and the torso's pose,
-- Tests/motion/kick_setup.lua); both feet unless a side is given. Figures: the toe's forward speed
-- just before contact (joint velocities + FK + the torso's truth), the ball's speed after it and
-- 0.3 s later (rolling by then), the distance, the robot's turn. A ball rolling at 1.6 m/s rolls
-- about 2 m on this carpet (Config/platforms/Sim/sim.lua); off the foot it slides first and keeps ~0.6 of
-- its speed unless the foot gives it topspin.
local function kick_one(side, gap)
  local r0 = ks.setup(Sim, Motion, wait, side, gap)
  local b0 = r0.ball
  local falls0 = motion.falls[0]
  Motion.request('kick_' .. side)
  local t0 = Body.get_time()
  local dt = 0.008
  local toe_v, toe_contact, t_contact, launch, rolling, prev = 0, nil, nil, 0, nil, nil
  while Body.get_time() - t0 < 2.5 do
    wait(dt)
    local r = Sim.truth()
    local v = ks.toe_velocity(side, r, prev, dt)
    local bs = math.sqrt(r.ball.vx ^ 2 + r.ball.vy ^ 2)
    if bs > 0.05 and not toe_contact then toe_contact, t_contact = toe_v, Body.get_time() end
    if toe_contact and bs > launch then launch = bs end
    if t_contact and not rolling and Body.get_time() - t_contact >= 0.3 then rolling = bs end
    toe_v = math.cos(r.yaw) * v[1] + math.sin(r.yaw) * v[2]
    prev = r
  end
  wait(6)
  local r1 = Sim.truth()
  local d = math.sqrt((r1.ball.x - b0.x) ^ 2 + (r1.ball.y - b0.y) ^ 2)
  note('kick %s: toe forward speed before contact %.2f m/s, ball speed after contact %.2f m/s, 0.3 s ' ..
    'later (rolling) %.2f m/s; ball travelled %.2f m; the robot turned %.2f rad', side, toe_contact or 0, launch,
    rolling or 0, d, wrap(r1.yaw - r0.yaw))
  local least = targets.kick.least
  tap(d >= least, string.format('kick %s: a ball (its centre %.2f m ahead of the toe) travels >= %.1f m (%.2f m)',
    side, gap, least, d))
  wait(1)
  -- a fall and a stand-up during the waits would end in stance too: the fall counter must not move
  tap(motion.falls[0] == falls0 and not Sim.truth().fallen and Motion.state() == 'stance',
    string.format('kick %s: stays up (falls during the kick: %d), back in stance', side, motion.falls[0] - falls0))
end

function scenarios.kick(side, gap)
  gap = tonumber(gap) or 0.1
  if side == 'left' or side == 'right' then return kick_one(side, gap) end
  kick_one('left', gap)
  kick_one('right', gap)
end

-- largest sideways push (N for 0.1 s) survived while walking at 0.2 m/s forward
-- pushmax [LABEL] [side|forward]: bisects the largest push (N x 0.1 s on the torso, sideways to the left
-- or forwards) survived while walking forward at 0.2 m/s (the Hubo: the walk config's velLimitX / 2)
function scenarios.pushmax(label, dir)
  -- the search's upper end scales with the body's mass (40 N for a 3 kg robot)
  local lo, hi = 0, 13 * require('kinematics').load().mass
  local v = math.min(0.2, Walk.get('velLimitX')[2] / 2)
  -- survived if survived at four moments of the gait cycle (each step's start, middle), both sides
  local function survives(f)
    for k = 0, 3 do
      start_clean()
      Motion.request('walk')
      Walk.set_velocity(v, 0, 0)
      wait(3 + k * Walk.get('tStep') / 2)
      if ks.push_falls(Sim, Motion, wait_until, dir, f) then
        note('pushmax: %.1f N x 0.1 s fell at moment %d (%d x tStep / 2 into the gait)', f, k, k)
        return false
      end
    end
    return true
  end
  lo = scenario_lib.bisect(lo, hi, 7, survives)
  dir = dir or 'side'
  note('pushmax %s %s: largest push survived while walking at %.2f m/s: %.1f N x 0.1 s = %.2f N s', label or '',
    dir, v, lo, lo * 0.1)
  print(string.format('pushmax %s %s %.3f', label or '', dir, lo * 0.1))
end

-- the README's REPL example: a head command from Body while the robot walks really moves the head
-- (the head is taken from motion) and the walk goes on; released, behavior's head_command counts again
function scenarios.head()
  start_clean()
  Motion.request('walk')
  Walk.set_velocity(0.2, 0, 0)
  wait(2)
  local a = Sim.truth()
  Body.set_head_command({ 0.5, -0.2 })
  wait(1)
  local h = Body.get_head_position()
  local owners = Motion.owners()
  note('head while walking: commanded (0.50, -0.20), at (%.3f, %.3f); owners: head %s, legs %s', h[1], h[2],
    owners.head, owners.lleg)
  tap(math.abs(h[1] - 0.5) < 0.03 and math.abs(h[2] + 0.2) < 0.03 and owners.head == 'caller'
    and Body.taken('head_pan'), 'Body.set_head_command moves the head while walking (taken from motion)')
  local b = Sim.truth()
  tap(Motion.state() == 'walk' and not b.fallen and math.sqrt((b.x - a.x) ^ 2 + (b.y - a.y) ^ 2) > 0.1,
    'the walk goes on meanwhile (no fall)')
  Body.release('head')
  wait(1)
  h = Body.get_head_position()
  note('released: head at (%.3f, %.3f), motion.head_command (%.2f, %.2f)', h[1], h[2], motion.head_command[0],
    motion.head_command[1])
  tap(Motion.owners().head == 'motion' and math.abs(h[1] - motion.head_command[0]) < 0.03
    and math.abs(h[2] - motion.head_command[1]) < 0.03, 'Body.release gives the head back to motion')
  Body.set_head_command({ -0.4, 0.1 })
  wait(0.5)
  Motion.request('stand')
  wait(1.5)
  h = Body.get_head_position()
  tap(Motion.owners().head == 'motion' and math.abs(h[1] - motion.head_command[0]) < 0.03,
    "a request whose state drives the head takes it back (Motion.request('stand'))")
end

-- top sustained speed along one axis: the fastest command (in steps) walked for 30 s with no fall
function scenarios.speed(axis, ...)
  local k = ({ x = 1, y = 2, a = 3 })[axis]
  local best = 0
  for _, v in ipairs({ ... }) do
    v = tonumber(v)
    start_clean()
    local cmd = { 0, 0, 0 }
    cmd[k] = v
    local vel, fell = walk_for(cmd[1], cmd[2], cmd[3], 30, 3)
    note('speed %s: command %.3f -> measured %.3f %s', axis, v, vel[k], fell and '(fell)' or '')
    if fell then break end
    best = math.max(best, math.abs(vel[k]))
  end
  print(string.format('speed %s %.3f', axis, best))
end

-- a straight walk whose speed ramps from v0 to v1 m/s at `rate` m/s per s (after 3 s at v0), then holds v1
-- for `hold` s (defaults 0.1, 0.4, 0.1, 5): it must not turn (the truth's heading from the ramp's start,
-- at most `max_drift` rad, default 0.25) nor fall, and walks on along its heading at 80% of v1 or more (the
-- feet slip a little on the carpet)
function scenarios.ramp(v0, v1, rate, hold, max_drift)
  v0, v1, rate, hold = tonumber(v0) or 0.1, tonumber(v1) or 0.4, tonumber(rate) or 0.1, tonumber(hold) or 5
  max_drift = tonumber(max_drift) or 0.25
  start_clean()
  local falls0 = Motion.falls()
  Motion.request('walk')
  Walk.set_velocity(v0, 0, 0)
  wait(3)
  local a = Sim.truth()
  local yaw, last, worst, fell = 0, a.yaw, 0, false
  local t0 = Body.get_time()
  local t_ramp = (v1 - v0) / rate
  local hold_start
  while Body.get_time() - t0 < t_ramp + hold do
    local t = Body.get_time() - t0
    Walk.set_velocity(math.min(v1, v0 + rate * t), 0, 0)
    wait(0.1)
    local s = Sim.truth()
    yaw = yaw + wrap(s.yaw - last)
    last = s.yaw
    worst = math.max(worst, math.abs(yaw))
    if not hold_start and t >= t_ramp then hold_start = { s, Body.get_time() } end
    if s.fallen or Motion.state() ~= 'walk' or Motion.falls() > falls0 then fell = true break end
  end
  local b = Sim.truth()
  local along = 0
  if hold_start and not fell then
    local h, dt = hold_start[1], Body.get_time() - hold_start[2]
    local c, sn = math.cos(b.yaw), math.sin(b.yaw)
    along = (c * (b.x - h.x) + sn * (b.y - h.y)) / dt
  end
  note('ramp %.2f -> %.2f m/s at %.2f m/s/s, %.0f s held: heading change %.3f rad at the end, %.3f at most; ' ..
    'speed along the heading while held %.3f m/s%s', v0, v1, rate, hold, yaw, worst, along, fell and ' (fell)' or '')
  print(string.format('ramp drift %.3f max %.3f along %.3f fell %d', yaw, worst, along, fell and 1 or 0))
  tap(not fell, 'no fall in the ramp and the hold')
  tap(worst < max_drift, string.format('a straight walk does not turn: heading change at most %.3f rad < %.2f',
    worst, max_drift))
  tap(along >= 0.8 * v1, string.format('walks on along its heading at %.3f m/s >= %.2f', along, 0.8 * v1))
end

local f = scenarios[name]
if not f then
  tap(false, 'unknown scenario ' .. tostring(name))
  os.exit(1)
end
f(select(2, unpack(arg)))
Walk.set_velocity(0, 0, 0)
