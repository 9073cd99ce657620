-- Whole-body control on the OP3 in the sim (Tests/wbc/wbc_sim_test.sh): the same controller and only
-- config. From stance, Motion.request('wbc'); the centre of mass over the left sole; the right sole
-- lifted 5 cm and held 10 s; put down again. Measured on the simulated robot: its truth (fallen,
-- tilt) and the feet from the measured joint angles through the legs' kinematics, turned by the
-- torso's true roll and pitch. Prints TAP and the figures.
-- luacheck: globals Sim Motion WBC wait Body
package.path = os.getenv('HRP_ROOT') .. '/Tests/motion/?.lua;' .. package.path
local ks = require('kick_setup')
local sc = require('Tests.scenario_lib').new(wait, Body)
local tap = sc.tap
local Config = require('Config')
local kin = require('kinematics')


-- The right sole's height above the left one, and the feet's mid-point's sideways offset from the
-- COM (world axes, from the measured angles and the torso's true roll and pitch).
local model = kin.load()
local function feet()
  local q = {}
  for i, name in ipairs(Body.joint_names()) do q[i] = Body.get_position(name) end
  local li, ri = {}, {}
  for k, name in ipairs({ 'hip_yaw', 'hip_roll', 'hip_pitch', 'knee', 'ank_pitch', 'ank_roll' }) do
    li[k] = Body.get_position('l_' .. name)
    ri[k] = Body.get_position('r_' .. name)
  end
  local l, r, com = model:leg_fk('l', li), model:leg_fk('r', ri), model:com(q)
  local t = Sim.truth()
  local cr, sr, cp, sp = math.cos(t.roll), math.sin(t.roll), math.cos(t.pitch), math.sin(t.pitch)
  local function world(v)   -- R = Ry(pitch) Rx(roll) applied to a torso-frame vector
    local y = cr * v[2] - sr * v[3]
    local z1 = sr * v[2] + cr * v[3]
    return { cp * v[1] + sp * z1, y, -sp * v[1] + cp * z1 }
  end
  local lw, rw, cw = world(l), world(r), world(com)
  return rw[3] - lw[3], cw[2] - lw[2], t
end

ks.need_motion(wait, tap)
Motion.request('stand')
wait(2)
Motion.request('wbc')
wait(1)
local s = WBC.status()
tap(Motion.state() == 'wbc' and s.active and s.feasible, 'the wbc state runs, its tasks feasible (state '
  .. Motion.state() .. ')')

-- the COM over the left sole (the walk's stance puts the soles footY off the middle)
local footY = Config.load('walk').footY
WBC.set_target('com', { 0, footY })
wait(2.5)
local lift0, com_off = feet()
print(string.format('# COM over the left sole: %.1f mm off it sideways', com_off * 1e3))
tap(math.abs(com_off) < 0.01, 'the centre of mass moves over the left sole (within 1 cm)')
local seq = WBC.set_target('r_sole', { 0, -footY, 0.05 })
wait(2)
local st = WBC.status()
tap(st.last.seq == seq and st.last.ok, 'the right sole released and given a target ' .. tostring(st.last.error or ''))
local worst_lift, worst_tilt, fell = 1, 0, false
for _ = 1, 100 do
  wait(0.1)
  local lift, _, t = feet()
  worst_lift = math.min(worst_lift, lift - lift0)
  worst_tilt = math.max(worst_tilt, math.abs(t.roll), math.abs(t.pitch - 0.08))
  fell = fell or t.fallen
end
print(string.format('# right foot lifted by at least %.1f mm for 10 s; torso tilt at most %.3f rad; fallen %s',
  worst_lift * 1e3, worst_tilt, tostring(fell)))
tap(not fell and Motion.state() == 'wbc', 'stands on one foot 10 s without a fall')
tap(worst_lift > 0.045, string.format('the right foot stays lifted 5 cm (at least %.1f mm)', worst_lift * 1e3))
WBC.set_target('r_sole', { 0, -footY, 0 })
wait(2)
WBC.set_target('r_sole', nil)
WBC.set_target('com', { 0, 0 })
wait(2)
Motion.request('stand')
wait(2)
tap(Motion.state() == 'stance' and not Sim.truth().fallen, 'puts the foot down and goes back to stance')
print('1..' .. sc.count)
