-- Whole-body control on the Hubo2+ in the sim (Tests/wbc/wbc_sim_test.sh): from stance,
-- Motion.request('wbc'); five right-hand targets up to 0.45 m ahead of the stance frame, some beyond
-- the arm's reach without the torso; each must be reached within 2 cm in 3 s, measured on the
-- simulated robot (Sim.link_truth of the palm), with no fall, the soles moving under 1 cm and the
-- measured ZMP (the feet's F/T sensors, Tests/wbc/zmp_margin.lua) inside the soles' support polygon
-- throughout each reach. A target 1.5 m ahead is flagged infeasible and the robot keeps standing.
-- Prints TAP and the figures.
-- luacheck: globals Sim Motion WBC wait Body
package.path = os.getenv('HRP_ROOT') .. '/Tests/wbc/?.lua;' .. package.path
local scene = require('wbc_scene')
local zmp_margin = require('zmp_margin')
local sc = require('Tests.scenario_lib').new(wait, Body)
local tap = sc.tap
local dist, xyz = scene.dist, scene.xyz

scene.start(wait, tap)
local l0, r0 = Sim.link_truth('l_sole'), Sim.link_truth('r_sole')
local frame = scene.stance_frame()
local to_field = frame.to_field

local targets = { { 0.30, -0.25, 0.80 }, { 0.35, -0.25, 0.90 }, { 0.40, -0.15, 0.85 }, { 0.45, -0.20, 0.75 },
  { 0.25, -0.35, 1.00 } }
local zm = zmp_margin.new(Sim, require('shm'))
local worst_hand, worst_sole, fell, worst_margin, unloaded = 0, 0, false, math.huge, 0
for i, t in ipairs(targets) do
  WBC.set_target('r_palm', t)
  -- the measured ZMP every 0.02 s of the 3 s: its smallest margin to the support polygon's edge
  zm:feet()
  local margin, at = math.huge, nil
  for _ = 1, 150 do
    wait(0.02)
    local m, zx, zy = zm:margin()
    if not m then unloaded = unloaded + 1 elseif m < margin then margin, at = m, { zx, zy } end
  end
  -- where it came closest to an edge, in the stance frame
  local near = frame.to_stance({ at and at[1] or 0 / 0, at and at[2] or 0 / 0, 0 })
  print(string.format('# target %d: measured ZMP at least %.1f mm inside the support polygon (closest at %.3f, %.3f '
    .. 'in the stance frame)', i, margin * 1e3, near[1], near[2]))
  worst_margin = math.min(worst_margin, margin)
  local hand = dist(xyz(Sim.link_truth('r_palm')), to_field(t))
  local sole = math.max(dist(xyz(Sim.link_truth('l_sole')), xyz(l0)), dist(xyz(Sim.link_truth('r_sole')), xyz(r0)))
  local st = WBC.status()
  local task = st.tasks.r_palm or {}
  print(string.format('# target %d (%.2f, %.2f, %.2f): palm %.1f mm off (model %.1f mm), soles moved %.1f mm, %s',
    i, t[1], t[2], t[3], hand * 1e3, (task.error or 0) * 1e3, sole * 1e3, task.feasible and 'feasible' or 'infeasible'))
  worst_hand, worst_sole = math.max(worst_hand, hand), math.max(worst_sole, sole)
  fell = fell or Sim.truth().fallen
end
tap(worst_hand < 0.02, string.format('five targets up to 0.45 m ahead reached within 2 cm in 3 s (worst %.1f mm)',
  worst_hand * 1e3))
tap(not fell and Motion.state() == 'wbc', 'no fall')
tap(worst_sole < 0.01, string.format('the soles moved under 1 cm (%.1f mm)', worst_sole * 1e3))
tap(worst_margin > 0 and unloaded == 0, string.format('the measured ZMP inside the feet throughout each reach '
  .. '(smallest margin %.1f mm to the support polygon; %d samples with no foot loaded)', worst_margin * 1e3, unloaded))
print(string.format('# controller step: %.0f us of CPU', WBC.status().tick_us))

-- holding a target, a 60 N push on the torso for 0.2 s (forwards, then sideways): survived, the hand
-- back within 2 cm 3 s later
local hold = { 0.35, -0.25, 0.90 }
WBC.set_target('r_palm', hold)
wait(3)
for _, push in ipairs({ { 60, 0, 'forwards' }, { 0, 60, 'sideways' } }) do
  local during = 0
  Sim.push(push[1], push[2], 0.2)
  for _ = 1, 5 do
    wait(0.1)
    during = math.max(during, dist(xyz(Sim.link_truth('r_palm')), to_field(hold)))
  end
  wait(2.5)
  local after = dist(xyz(Sim.link_truth('r_palm')), to_field(hold))
  print(string.format('# pushed 60 N %s for 0.2 s: palm up to %.1f mm off, %.1f mm 3 s later', push[3], during * 1e3,
    after * 1e3))
  print('# motion state ' .. Motion.state() .. ', falls ' .. Motion.falls())
  tap(not Sim.truth().fallen and after < 0.02 and Motion.state() == 'wbc',
    string.format('a 60 N push %s while holding: no fall, the hand back within 2 cm (%.1f mm)', push[3], after * 1e3))
end

WBC.set_target('r_palm', { 1.5, -0.3, 0.9 })
local flagged, sigma, task = false, 1, {}
for _ = 1, 30 do
  wait(0.1)
  local st = WBC.status()
  task = st.tasks.r_palm or {}
  if task.enabled and not task.feasible and not st.feasible and not flagged then
    flagged, sigma = true, task.sigma_min
  end
end
tap(flagged, string.format('a target 1.5 m ahead: flagged infeasible (sigma_min %.3f)', sigma))
local t = Sim.truth()
print(string.format('# out of reach for 3 s: held %s, state %s, torso pitch %.3f rad', tostring(task.held),
  Motion.state(), t.pitch))
tap(task.held and Motion.state() == 'wbc' and not t.fallen and t.pitch < 0.3,
  'the hand then holds where it got to, the torso within its lean bound, the robot standing in the wbc state')
WBC.set_target('r_palm', nil)
wait(3)
Motion.request('stand')
wait(3)
tap(Motion.state() == 'stance' and not Sim.truth().fallen, 'back to stance, standing')
print('1..' .. sc.count)
