-- Scenario of Tests/motion/hoap3_touch_test.sh (./run_repl in lockstep, ROBOT=hoap3): the HOAP-3
-- stands in front of a wall (the site's sim.lua puts its face at x = WALL_X), touches it with both
-- hands (Motion.request('touch'): both arms swing up until each wrist's force sensor reads a touch),
-- holds 3 s, then stands again. Prints TAP and the figures.
--   hoap3_touch.lua WALL_X
-- luacheck: read globals Sim Body Motion wait dcm_sensor
local sc = require('Tests.scenario_lib').new(wait, Body)
local tap, note = sc.tap, sc.note
local wall_x = assert(tonumber(arg[1]), 'usage: hoap3_touch.lua WALL_X')
local threshold = require('Config').load('touch').force

-- |force| at a wrist sensor: dcm.sensor.ft holds the left foot, right foot, left hand, right hand
local LEFT, RIGHT = 12, 18
local function wrist_force(k)
  local f = dcm_sensor.ft
  return math.sqrt(f[k] ^ 2 + f[k + 1] ^ 2 + f[k + 2] ^ 2)
end

wait(2.0)
local falls0 = Motion.falls()
local lrest, rrest = wrist_force(LEFT), wrist_force(RIGHT)
note('standing: wrist sensors read %.2f N (left), %.2f N (right): the weight below them', lrest, rrest)
Motion.request('touch')
-- both arms stop on the wall within the sweep (1.9 rad at 0.3 rad/s: 6.2 s), or never
local t0, touched = Body.get_time(), nil
local lmax, rmax = 0, 0
while Body.get_time() - t0 < 9.0 do
  wait(0.05)
  local l, r = wrist_force(LEFT) - lrest, wrist_force(RIGHT) - rrest
  lmax, rmax = math.max(lmax, l), math.max(rmax, r)
  if not touched and l > threshold and r > threshold then touched = Body.get_time() - t0 end
end
-- holding: the forces and where the hands are, over 3 s
local lmin, rmin, gap_max = math.huge, math.huge, 0
for _ = 1, 30 do
  wait(0.1)
  lmin, rmin = math.min(lmin, wrist_force(LEFT) - lrest), math.min(rmin, wrist_force(RIGHT) - rrest)
  for _, h in ipairs({ 'l_hand', 'r_hand' }) do
    gap_max = math.max(gap_max, math.abs(wall_x - Sim.link_truth(h).x))
  end
end
local lh, rh = Sim.link_truth('l_hand'), Sim.link_truth('r_hand')
note('touch: both wrists %.1f N over rest %s s after the request; holding 3 s: at least %.2f N (left), %.2f N (right); '
  .. 'peaks %.2f / %.2f N', threshold, touched and string.format('%.2f', touched) or 'never', lmin, rmin, lmax, rmax)
note('hands at x %.3f / %.3f m, z %.3f / %.3f m; the wall\'s face at x %.3f m', lh.x, rh.x, lh.z, rh.z, wall_x)
tap(touched ~= nil, 'both wrists feel the wall within the sweep')
tap(lmin > threshold and rmin > threshold,
  string.format('both hands stay in contact while holding: %.2f / %.2f N over rest, threshold %.1f N', lmin, rmin,
    threshold))
tap(gap_max < 0.02, string.format('the hands are within 2 cm of the wall plane while holding: %.3f m', gap_max))
tap(lmax < 20 and rmax < 20, string.format('the arms stop on the touch, no hard push: peaks %.2f / %.2f N', lmax, rmax))
Motion.request('stand')
wait(3.0)
tap(not Sim.truth().fallen and Motion.falls() == falls0, 'the robot stays standing throughout')
tap(Motion.state() == 'stance', 'back to stance after the touch: ' .. Motion.state())
