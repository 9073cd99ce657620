-- Scenario of Tests/motion/hoap3_dance_test.sh (./run_repl in lockstep, ROBOT=hoap3): the HOAP-3
-- plays its dance routine (Config/robots/hoap3/routines/dance.lua through Lib/routine.lua: whole-body
-- moves standing and quarter turns on the spot), ROUNDS rounds (default: the routine's). The measured
-- ZMP (the foot pressure sensors) and the sim's true centre of pressure against the support polygon
-- of the feet carrying weight, every 0.05 s
-- (Tests/wbc/zmp_margin.lua), by kind of step; the standing moves' must stay inside. Prints TAP and
-- the figures.
--   hoap3_dance.lua [ROUNDS]
-- luacheck: read globals Sim Body Motion wait
package.path = os.getenv('HRP_ROOT') .. '/Tests/wbc/?.lua;' .. package.path
local sc = require('Tests.scenario_lib').new(wait, Body)
local tap, note = sc.tap, sc.note
local routine = require('routine')
local zmp_margin = require('zmp_margin')

local rounds = tonumber(arg[1])
wait(2.0)
local zm = zmp_margin.new(Sim, require('shm'))
-- the smallest margin by kind of step, where, and the samples with no foot loaded: the measured
-- ZMP's (the foot pressure sensors') and the sim's truth's (the ground's forces on the soles: on an
-- edge while a foot tips about it)
local worst, at, tworst, tat, samples, unloaded = {}, {}, {}, {}, 0, 0
local report = routine.play('dance', wait, { rounds = rounds, each = function(step, k, round)
  zm:feet()
  local m, zx, zy = zm:margin()
  samples = samples + 1
  if not m then unloaded = unloaded + 1 return end
  local kind = ({ skill = 'standing moves', walk = 'turning', stand = 'standing' })[routine.kind(step)]
  if m < (worst[kind] or math.huge) then
    worst[kind] = m
    at[kind] = string.format('round %d step %d, %.2f s, at (%.3f, %.3f)', round, k, Body.get_time(), zx, zy)
  end
  local tm, tx, ty = zm:truth_margin()
  if tm and tm < (tworst[kind] or math.huge) then
    tworst[kind] = tm
    tat[kind] = string.format('round %d step %d, %.2f s, at (%.3f, %.3f)', round, k, Body.get_time(), tx, ty)
  end
end })
for kind, m in pairs(worst) do
  note('%s: the measured ZMP at least %.1f mm inside the support polygon (%s)', kind, m * 1e3, at[kind])
  note('%s: the true centre of pressure at least %.1f mm inside it (%s)', kind, (tworst[kind] or 0 / 0) * 1e3,
    tat[kind] or '-')
end
note('dance: %.1f s of robot time, %d steps, %d falls, %d ZMP samples (%d with no foot loaded)%s', report.seconds,
  report.steps, report.falls, samples, unloaded, report.stopped and ', stopped: ' .. report.stopped or '')
local expected = (rounds or routine.load('dance').rounds) * #routine.load('dance').steps
tap(report.stopped == nil and report.steps == expected,
  string.format('the routine plays to its end: %d of %d steps', report.steps, expected))
tap(report.falls == 0 and not Sim.truth().fallen, 'no fall')
-- the standing moves are the whole-body controller's: their ZMP must stay inside; the turns are the
-- walk's (its steps put the true centre of pressure on a sole's edge: printed above; the pressure
-- sensors, 12.5 mm inside the edges, cannot show it)
local standing = worst['standing moves'] or -math.huge
tap(standing > 0 and unloaded == 0, string.format('the measured ZMP inside the support polygon throughout the '
  .. 'standing moves: smallest margin %.1f mm, %d samples with no foot loaded', standing * 1e3, unloaded))
tap(Motion.state() == 'stance', 'standing at the end: ' .. Motion.state())
