-- Logs a kick tick by tick in the sim's lockstep (run by Tools/tune/kick_trace.sh): the kicking
-- leg's joint angles and velocities, the toe's velocity (relative to the torso from the joint
-- velocities and FK; in the world with the truth's torso motion), the torso and the ball
-- (Sim.truth()), the whole-body COM and capture point against the support foot's ankle, the
-- soles' loads and the support foot's yaw in the world (a spinning foot).
--   ./run_repl Tools/tune/kick_trace.lua SIDE OUT.csv [GAP]
-- GAP: m from the toe to the ball's centre (default 0.1). Prints "# " figures at the end,
-- among them where the ball met the foot (its centre in the foot's frame just before contact).
-- luacheck: globals Sim Motion wait arg Body
if not Sim then
  package.path = os.getenv('HRP_ROOT') .. '/Tests/motion/?.lua;' .. package.path
  Sim = require('sim_shim')
end
-- kick_measure beside this file; kick_setup and sim_shim with the scenarios they serve (Tests/motion)
local root = os.getenv('HRP_ROOT')
package.path = root .. '/Tools/tune/?.lua;' .. root .. '/Tests/motion/?.lua;' .. package.path
local ks = require('kick_setup')
local kin = require('kinematics')

local side, out, gap = arg[1] or 'left', arg[2] or 'kick.csv', tonumber(arg[3]) or 0.1
assert(require('kick_setup').wait_for_motion(wait), 'the motion process is not running')

require('kick_measure').apply_env(wait)   -- KICK_PARAMS=file.lua: a tuned set
local r0 = ks.setup(Sim, Motion, wait, side, gap)
local b0 = r0.ball
local bf0 = ks.ball_in_foot(side, Body.get_positions(), r0)

local f = assert(io.open(out, 'w'))
local names = { 'hip_yaw', 'hip_roll', 'hip_pitch', 'knee', 'ank_pitch', 'ank_roll' }
local sup = side == 'left' and 'r_' or 'l_'
local sside = side == 'left' and 'right' or 'left'
local model = kin.load()
local head = { 't', 'state', 'x', 'y', 'z', 'roll', 'pitch', 'yaw', 'bx', 'by', 'bz', 'bvx', 'bvy',
  'toe_x', 'toe_y', 'toe_z', 'toe_wz', 'toe_rvx', 'toe_rvz', 'toe_wvx', 'toe_wvy', 'toe_wvz', 'foot_pitch',
  'com_f', 'com_l', 'com_z', 'cp_f', 'cp_l', 'fz_kick', 'fz_sup', 'sfoot_yaw' }
for _, n in ipairs(names) do head[#head + 1] = 'q_' .. n end
for _, n in ipairs(names) do head[#head + 1] = 'qd_' .. n end
for _, n in ipairs({ 'hip_pitch', 'knee', 'ank_pitch' }) do head[#head + 1] = 'sq_' .. n end
for _, n in ipairs({ 'hip_pitch', 'knee', 'ank_pitch' }) do head[#head + 1] = 'sqd_' .. n end
f:write(table.concat(head, ','), '\n')

local STATES = { stance = 0, kick_left = 1, kick_right = 1, falling = 2 }
local DT = 0.008
Motion.request('kick_' .. side)
local t0 = Body.get_time()
local prev, prev_com
local peak_ball, peak_toe, toe_at_contact, t_contact, before, last = 0, 0, nil, nil, nil, nil
local fell = false
while Body.get_time() - t0 < 7 do
  wait(DT)
  local r = Sim.truth()
  local t = Body.get_time() - t0
  local q6, qd6 = ks.leg(side), ks.leg(side, Body.get_velocity)
  local wv, toe = ks.toe_velocity(side, r, prev, DT)
  local rv = ks.toe_velocity_in_torso(side, q6, qd6)
  local tw = ks.to_world(r, toe)
  local c, s = math.cos(r.yaw), math.sin(r.yaw)
  local fwd = c * wv[1] + s * wv[2]
  local bs = math.sqrt(r.ball.vx ^ 2 + r.ball.vy ^ 2)
  if bs > 0.05 and not t_contact then t_contact, toe_at_contact, before = t, fwd, last end
  if bs > peak_ball then peak_ball = bs end
  if fwd > peak_toe then peak_toe = fwd end
  fell = fell or r.fallen
  local com = ks.com_over_support(side, r)
  local cv = { 0, 0 }
  if prev_com then cv = { (com[1] - prev_com[1]) / DT, (com[2] - prev_com[2]) / DT } end
  prev_com = com
  local w0 = math.sqrt(9.81 / math.max(0.1, com[3]))
  local ff = Body.sensor.foot_force
  local qa = Body.get_positions()
  local foot_pitch = ks.foot_pitch(side, q6) + r.pitch
  last = { z = tw[3], vx = fwd, vz = wv[3], pitch = foot_pitch, ball = ks.ball_in_foot(side, qa, r) }
  local row = { t, STATES[Motion.state()] or 3, r.x, r.y, r.z, r.roll, r.pitch, r.yaw, r.ball.x, r.ball.y,
    r.ball.z, r.ball.vx, r.ball.vy, toe[1], toe[2], toe[3], tw[3], rv[1], rv[3], fwd, -s * wv[1] + c * wv[2], wv[3],
    foot_pitch, com[1], com[2], com[3], com[1] + cv[1] / w0, com[2] + cv[2] / w0,
    side == 'left' and ff[0] or ff[1], side == 'left' and ff[1] or ff[0],
    r.yaw + model:leg_fk(sside, ks.leg(sside))[6] }
  for k = 1, 6 do row[#row + 1] = q6[k] end
  for k = 1, 6 do row[#row + 1] = qd6[k] end
  for _, n in ipairs({ 'hip_pitch', 'knee', 'ank_pitch' }) do row[#row + 1] = Body.get_position(sup .. n) end
  for _, n in ipairs({ 'hip_pitch', 'knee', 'ank_pitch' }) do row[#row + 1] = Body.get_velocity(sup .. n) end
  for k = 1, #row do row[k] = string.format('%.5f', row[k]) end
  f:write(table.concat(row, ','), '\n')
  prev = r
end
f:close()
local b1 = Sim.truth().ball
local d = math.sqrt((b1.x - b0.x) ^ 2 + (b1.y - b0.y) ^ 2)
print(string.format('# kick %s gap %.3f (ball centre %+.3f %+.3f %+.3f m from the sole plate centre at stance): ' ..
  'ball travelled %.2f m; peak ball speed %.2f m/s; toe forward speed %.2f m/s at first ball motion (t=%.3f), ' ..
  'peak %.2f m/s; fallen %s, state %s', side, gap, bf0[1], bf0[2], bf0[3], d, peak_ball, toe_at_contact or 0,
  t_contact or -1, peak_toe, tostring(fell or Sim.truth().fallen), Motion.state()))
if before then
  print(string.format('# before contact: toe height %.3f m, forward %.2f m/s, up %.2f m/s, foot pitch %.2f rad ' ..
    '(toe down +); ball centre from the sole plate centre (foot frame) %+.3f %+.3f %+.3f m', before.z, before.vx,
    before.vz, before.pitch, before.ball[1], before.ball[2], before.ball[3]))
end
