-- Whole-body control on the Hubo2+ in the sim (Tests/wbc/wbc_sim_test.sh): from stance,
-- Motion.request('wbc'); five right-hand targets up to 0.45 m ahead of the stance frame, some beyond
-- the arm's reach without the torso; each must be reached within 2 cm in 3 s, measured on the
-- simulated robot (Sim.link_truth of the palm), with no fall and the soles moving under 1 cm. A
-- target 1.5 m ahead is flagged infeasible and the robot keeps standing. Prints TAP and the figures.
-- luacheck: globals Sim Motion WBC wait Body
package.path = os.getenv('HRP_ROOT') .. '/Tests/motion/?.lua;' .. package.path
local ks = require('kick_setup')
local sc = require('Tests.scenario_lib').new(wait, Body)
local tap = sc.tap


local function dist(a, b) return math.sqrt((a[1] - b[1]) ^ 2 + (a[2] - b[2]) ^ 2 + (a[3] - b[3]) ^ 2) end
local function xyz(p) return { p.x, p.y, p.z } end

ks.need_motion(wait, tap)
Motion.request('stand')
wait(3)
Motion.request('wbc')
wait(1)
tap(Motion.state() == 'wbc' and WBC.status().active, 'the wbc state runs (state ' .. Motion.state() .. ')')

-- the stance frame in the field: midway between the soles, x along their mean heading
local l0, r0 = Sim.link_truth('l_sole'), Sim.link_truth('r_sole')
local ox, oy, oz = (l0.x + r0.x) / 2, (l0.y + r0.y) / 2, (l0.z + r0.z) / 2
local yaw = (l0.yaw + r0.yaw) / 2
local function to_field(p)
  local c, s = math.cos(yaw), math.sin(yaw)
  return { ox + c * p[1] - s * p[2], oy + s * p[1] + c * p[2], oz + p[3] }
end

local targets = { { 0.30, -0.25, 0.80 }, { 0.35, -0.25, 0.90 }, { 0.40, -0.15, 0.85 }, { 0.45, -0.20, 0.75 },
  { 0.25, -0.35, 1.00 } }
local worst_hand, worst_sole, fell = 0, 0, false
for i, t in ipairs(targets) do
  WBC.set_target('r_palm', t)
  wait(3)
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
print(string.format('# controller step: %.0f us of CPU', WBC.status().tick_us))

WBC.set_target('r_palm', { 1.5, -0.3, 0.9 })
wait(3)
local st = WBC.status()
tap(not st.tasks.r_palm.feasible and not st.feasible and not Sim.truth().fallen,
  string.format('a target 1.5 m ahead: flagged infeasible (sigma_min %.3f), the robot standing',
    st.tasks.r_palm.sigma_min))
WBC.set_target('r_palm', nil)
wait(3)
Motion.request('stand')
wait(3)
tap(Motion.state() == 'stance' and not Sim.truth().fallen, 'back to stance, standing')
print('1..' .. sc.count)
