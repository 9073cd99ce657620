-- One stand-up trial (Tools/tune/standup_stats.sh runs one per sim): the robot stands, walks
-- forwards at 0.1 m/s for W s, is pushed over (DIR = 1 forwards, -1 backwards: 30 N along its
-- heading for 0.2 s) and gets up on its own. Prints one line:
--   RESULT dir D W w: up|down|nofall attempts A after T s: STATES
-- up = walking again, upright, within 20 s; attempts = stand-up motions played from each side
-- (front, back); nofall = the push did not topple it, or it fell before the push (no information).
-- luacheck: globals Sim Motion Walk wait Body
local W = tonumber(os.getenv('W') or '2')
local dir = tonumber(os.getenv('DIR') or '1')
package.path = os.getenv('HRP_ROOT') .. '/Tests/motion/?.lua;' .. package.path
local ks = require('kick_setup')
if not ks.wait_for_motion(wait) then
  print('RESULT error: the motion process is not running')
  os.exit(1)
end
Sim.reset() wait(0.2)
-- the reset puts the ball on the centre spot: out of the way first, then the robot there
Sim.teleport_ball(3, 2) Sim.teleport_robot(0, 0, 0) wait(0.2)
Motion.request('stand') wait(2)
Motion.request('walk') Walk.set_velocity(0.1, 0, 0) wait(W)
local f0 = Motion.falls()
local before = Motion.state()
local yaw = Sim.truth().yaw
Sim.push(30 * dir * math.cos(yaw), 30 * dir * math.sin(yaw), 0.2)
local t0 = Body.get_time()
local seq, last = {}, nil
local attempts = { standup_front = 0, standup_back = 0 }
local up = false
while Body.get_time() - t0 < 20 do
  wait(0.05)
  local s = Motion.state()
  if s ~= last then
    seq[#seq + 1] = s
    if attempts[s] then attempts[s] = attempts[s] + 1 end
    last = s
  end
  if Motion.falls() > f0 and s == 'walk' and not Sim.truth().fallen then up = true break end
end
local outcome = up and 'up' or 'down'
if before ~= 'walk' or Motion.falls() == f0 then outcome = 'nofall' end
print(string.format('RESULT dir %d W %s: %s attempts front %d back %d after %.1f s: %s', dir, W, outcome,
  attempts.standup_front, attempts.standup_back, Body.get_time() - t0, table.concat(seq, ' ')))
