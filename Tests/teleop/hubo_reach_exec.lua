-- Teleoperation's executor on the Hubo2+ in the sim (Tests/teleop/exec_sim_test.sh, lockstep): from a
-- settled stance, Motion.request('teleop'); the key pose "reach" validated from the joints' commands
-- (Lib/teleop.lua), sent in chunks with the operator's heartbeat (Lib/Teleop.lua) and played; the
-- right palm must end within 2 cm of the key pose's target (Sim.link_truth, the target put in the
-- field through the soles' stance frame). Before it, a copy sent with one angle changed is refused at
-- start and the robot does not move; a bad key pose is refused by the validator. After it, a second
-- trajectory (to "ready") stopped 0.8 s in: the robot holds where it was stopped, no fall. Prints TAP
-- and the figures.
-- luacheck: globals Sim Motion Body wait
package.path = os.getenv('HRP_ROOT') .. '/Tests/wbc/?.lua;' .. os.getenv('HRP_ROOT') .. '/Tests/motion/?.lua;'
  .. package.path
local ks = require('kick_setup')
local scene = require('wbc_scene')
local teleop = require('teleop')
local Teleop = require('Teleop')
local sc = require('Tests.scenario_lib').new(wait, Body)
local tap, note = sc.tap, sc.note
local dist, xyz = scene.dist, scene.xyz

-- the clock runs in steps of 0.02 s with the operator's heartbeat
local function run(s)
  local t = 0
  while t < s - 1e-9 do
    Teleop.heartbeat()
    wait(0.02)
    t = t + 0.02
  end
end

ks.need_motion(wait, tap)
Motion.request('stand')
wait(3)
Motion.request('teleop')
run(1)
tap(Motion.state() == 'teleop' and Teleop.status().link_ok, 'the teleop executor runs, the link alive (state '
  .. Motion.state() .. ')')

local v = teleop.validator()
local kp = teleop.keypose('reach')
local clock = os.clock()
local plan, why = v:plan(Body.get_commands(), { kp })
tap(plan ~= nil, 'reach validated from the stance' .. (why and (': ' .. why.message) or ''))
if not plan then os.exit(1) end
local f = plan.figures
note('reach: %d samples, model palm %.1f mm off, COM >= %.1f mm inside, peak joint speed %.0f %% of the bound\'s '
  .. 'actuator, validated in %.2f s of CPU', plan.n, f.reach * 1e3, f.com_margin * 1e3, f.speed_share * 100,
  os.clock() - clock)
local bad, bwhy = v:plan(Body.get_commands(),
  { teleop.keypose_file(os.getenv('HRP_ROOT') .. '/Tests/teleop/keyposes/out_of_reach.lua') })
tap(bad == nil and bwhy.reason == 'reach', 'out_of_reach refused for reach: ' .. (bwhy and bwhy.message or '?'))

-- a copy with one angle changed in transit: refused, nothing moves
local palm0 = xyz(Sim.link_truth('r_palm'))
local id = Teleop.send(plan, wait, { corrupt = 3 })
Teleop.start(id)
run(0.5)
local s = Teleop.status()
local moved = dist(xyz(Sim.link_truth('r_palm')), palm0)
tap(s.state ~= 'running' and not s.last.ok and s.reason:find('checksum') and moved < 0.002,
  string.format('a corrupted trajectory never starts '
  .. '(%s; the palm moved %.1f mm)', s.reason, moved * 1e3))

-- the trajectory whole: played
local frame = scene.stance_frame()
local target = frame.to_field(kp.limbs.rhand.pos)
id = Teleop.send(plan, wait)
s = Teleop.status()
tap(s.state == 'ready' and s.loaded == id, string.format('the trajectory arrived whole (%d samples, state %s)',
  s.received, s.state))
Teleop.start(id)
run(plan.n * plan.dt + 0.5)
s = Teleop.status()
local off = dist(xyz(Sim.link_truth('r_palm')), target)
tap(s.state == 'done', 'played to its end (state ' .. s.state .. ')')
tap(off < 0.02, string.format('the palm within 2 cm of the key pose\'s target (%.1f mm)', off * 1e3))
tap(not Sim.truth().fallen, 'no fall')

-- a second trajectory, stopped 0.8 s in: it holds
local two = v:plan(Body.get_commands(), { teleop.keypose('ready') })
tap(two ~= nil, 'ready validated from the reach')
if not two then os.exit(1) end
id = Teleop.send(two, wait)
Teleop.start(id)
run(0.8)
Teleop.stop()
run(0.1)
local at_stop = xyz(Sim.link_truth('r_palm'))
local sample = Teleop.status().sample
run(2)
s = Teleop.status()
local drift = dist(xyz(Sim.link_truth('r_palm')), at_stop)
tap(s.state == 'stopped' and s.sample == sample and sample < two.n, string.format('stopped at sample %d of %d '
  .. '(%s)', sample, two.n, s.reason))
tap(drift < 0.005, string.format('held where it stopped: the palm moved %.1f mm in the 2 s after', drift * 1e3))
tap(not Sim.truth().fallen and Motion.state() == 'teleop', 'no fall')
