-- The waistbot test body in the sim (Tests/motion/waist_test.sh): the same motion code stands and
-- walks a body with a waist that carries the arms and head, wrists, and a bus order unlike its tree;
-- the waist, which no motion state drives, holds where a caller put it. Prints TAP.
-- luacheck: globals Sim Motion Walk wait Body
package.path = os.getenv('HRP_ROOT') .. '/Tests/motion/?.lua;' .. package.path
local ks = require('kick_setup')
local n = 0
local function tap(ok, msg)
  n = n + 1
  print(string.format('%s %d - %s', ok and 'ok' or 'not ok', n, msg))
  io.stdout:flush()
end

local motion = ks.wait_for_motion(wait)
tap(motion ~= nil, 'the motion process runs on the waistbot')
if not motion then os.exit(1) end

-- the robot as the sim placed it: standing still at its start
Motion.request('stand')
wait(2)
tap(Motion.state() == 'stance' and not Sim.truth().fallen, 'stands (state ' .. Motion.state() .. ')')
-- the waist: no state drives it, so a command from outside stays
Body.set_command('waist_yaw', 0.3)
wait(1)
print(string.format('# waist: commanded 0.300, at %.3f, owner %s', Body.get_position('waist_yaw'),
  tostring(Motion.owner('waist_yaw'))))
tap(math.abs(Body.get_position('waist_yaw') - 0.3) < 0.02, 'the waist turns to a command from outside')
-- walk with the waist turned (WAIST env: another angle)
local WALK_WAIST = tonumber(os.getenv('WAIST') or '0.3')
Body.set_command('waist_yaw', WALK_WAIST)
wait(0.5)
local a = Sim.truth()
Motion.request('walk')
Walk.set_velocity(0.15, 0, 0)
wait(6)
local b = Sim.truth()
local d = math.sqrt((b.x - a.x) ^ 2 + (b.y - a.y) ^ 2)
print(string.format('# walked %.2f m in 6 s, waist at %.3f, state %s, fallen %s, falls %d', d,
  Body.get_position('waist_yaw'), Motion.state(), tostring(b.fallen), Motion.falls()))
tap(not b.fallen and Motion.state() == 'walk', 'walks 6 s without a fall')
tap(d > 0.4, string.format('walks forward (%.2f m in 6 s)', d))
tap(math.abs(Body.get_position('waist_yaw') - WALK_WAIST) < 0.03,
  string.format('the waist holds its command (%.2f) while walking', WALK_WAIST))
Walk.set_velocity(0, 0, 0)
Motion.request('stand')
wait(3)
tap(Motion.state() == 'stance' and not Sim.truth().fallen, 'stops into stance')
print('1..' .. n)
