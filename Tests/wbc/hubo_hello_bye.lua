-- The skill hello_bye on the Hubo2+ in the sim (Tests/wbc/wbc_sim_test.sh; the skill:
-- Config/robots/hubo2plus/wbc_skills/hello_bye.lua): Motion.request('wbc', { skill = 'hello_bye' })
-- from stance; the right palm goes up beside the head, waves out and in three times and comes back
-- down. Each state must be reached in its order, each wave state left with the palm (measured on the
-- simulated robot, Sim.link_truth) within 3 cm of the state's target, the palm back within 2 cm of
-- where it started, no fall. Prints TAP and the figures.
-- luacheck: globals Sim Motion WBC wait Body
package.path = os.getenv('HRP_ROOT') .. '/Tests/motion/?.lua;' .. os.getenv('HRP_ROOT') .. '/Tests/wbc/?.lua;'
  .. package.path
local ks = require('kick_setup')
local scene = require('wbc_scene')
local sc = require('Tests.scenario_lib').new(wait, Body)
local tap = sc.tap
local Config = require('Config')
local dist, xyz = scene.dist, scene.xyz

ks.need_motion(wait, tap)
Motion.request('stand')
wait(3)
local start = xyz(Sim.link_truth('r_palm'))
-- the stance frame in the field (the state sets it at its start: midway between the soles)
local to_field = scene.stance_frame().to_field
local skill = Config.load('wbc_skills/hello_bye')
local function target_of(state)
  local st = skill.states[state]
  local t = Config.optional(st, 'tasks') and Config.optional(st.tasks, 'r_palm')
  return t and to_field(t.target)
end

Motion.request('wbc', { skill = 'hello_bye' })
wait(0.1)
local s = WBC.status()
tap(Motion.state() == 'wbc' and s.skill.name == 'hello_bye' and s.skill.last.ok,
  string.format("Motion.request('wbc', { skill = 'hello_bye' }) runs it (state %s, skill '%s', state '%s' %s)",
    Motion.state(), s.skill.name, s.skill.state, s.skill.last.error or ''))

-- every 0.02 s: the skill's state, the palm's truth; a state's last sample is its palm error
local order, errors, times = {}, {}, {}
local fell, last = false, nil
local t_end = Body.get_time() + 40
while Body.get_time() < t_end do
  local st = WBC.status()
  local name = st.skill.state
  if name ~= order[#order] then order[#order + 1] = name end
  local target = target_of(name)
  errors[#order] = target and dist(xyz(Sim.link_truth('r_palm')), target) or nil
  times[#order] = st.skill.time
  fell = fell or Sim.truth().fallen
  if name == 'bye' then
    last = last or Body.get_time()
    if Body.get_time() - last > 5 then break end
  end
  wait(0.02)
end
local back = dist(xyz(Sim.link_truth('r_palm')), start)

local want = { 'hello', 'wave_out', 'wave_in', 'wave_out', 'wave_in', 'wave_out', 'wave_in', 'bye' }
-- the shortest `after` of a state's rules: a state left before it was left by reaching its target
local function after_of(name)
  local nx = Config.optional(skill.states[name], 'next')
  if not nx then return math.huge end
  local a = math.huge
  for _, r in ipairs(rawget(nx, 'go') and { nx } or nx) do
    a = math.min(a, Config.optional(r, 'after', math.huge))
  end
  return a
end
local figs, worst, by_time = {}, 0, 0
for i, name in ipairs(order) do
  figs[i] = string.format('%s %.1f s', name, times[i] or 0)
  if errors[i] and i < #order then
    figs[i] = figs[i] .. string.format(' (palm %.1f mm off)', errors[i] * 1e3)
    worst = math.max(worst, errors[i])
    if (times[i] or 0) >= after_of(name) - 0.05 then by_time = by_time + 1 end
  end
end
print('# ' .. table.concat(figs, ' > '))
local seq = table.concat(order, ' ')
tap(seq == table.concat(want, ' '), 'every state reached in order: ' .. seq)
tap(worst < 0.03 and by_time == 0 and #order == #want, string.format('each state left on reaching its target '
  .. '(none by its time-out: %d), the palm then within 3 cm of it (Sim.link_truth; worst %.1f mm)', by_time,
  worst * 1e3))
tap(back < 0.02, string.format('the palm back within 2 cm of where it started 5 s into bye (%.1f mm)', back * 1e3))
tap(not fell and Motion.state() == 'wbc', 'no fall, still in the wbc state')
Motion.request('stand')
wait(3)
tap(Motion.state() == 'stance' and not Sim.truth().fallen, 'back to stance, standing')
print('1..' .. sc.count)
