-- Logs a kick tick by tick in the sim's lockstep (run by Tests/motion/kick_trace.sh): the kicking
-- leg's joint angles and velocities, the toe's velocity (relative to the torso from the joint
-- velocities and FK; in the world from the truth's torso pose), the torso and the ball (Sim.truth()).
--   ./run_repl Tests/motion/kick_trace.lua SIDE OUT.csv [GAP]
-- GAP: m from the toe to the ball's centre (default 0.1). Prints "# " figures at the end.
-- luacheck: globals Sim Motion wait arg Body
if not Sim then
  package.path = os.getenv('HRP_ROOT') .. '/Tests/motion/?.lua;' .. package.path
  Sim = require('sim_shim')
end
package.path = os.getenv('HRP_ROOT') .. '/Tests/motion/?.lua;' .. package.path
local ks = require('kick_setup')

local side, out, gap = arg[1] or 'left', arg[2] or 'kick.csv', tonumber(arg[3]) or 0.1
local shm = require('shm')
local motion = shm.open('motion')
for _ = 1, 300 do
  if motion.tick[0] ~= 0 and Body.get_tick() - motion.tick[0] <= 2 then break end
  wait(0.1)
end

Sim.reset()
wait(0.2)
Sim.teleport_robot(-4.3, -3.3, math.atan2(6.6, 8.6))
Sim.teleport_ball(4.0, -3.5)
wait(0.2)
Motion.request('stand')
wait(2.5)
ks.place_ball(Sim, side, gap, Sim.truth())
wait(0.5)
local b0 = Sim.truth().ball

local f = assert(io.open(out, 'w'))
local names = { 'hip_yaw', 'hip_roll', 'hip_pitch', 'knee', 'ank_pitch', 'ank_roll' }
local sup = side == 'left' and 'r_' or 'l_'
local head = { 't', 'state', 'x', 'y', 'z', 'roll', 'pitch', 'yaw', 'bx', 'by', 'bz', 'bvx', 'bvy',
  'toe_x', 'toe_y', 'toe_z', 'toe_wz', 'toe_rvx', 'toe_rvz', 'toe_wvx', 'toe_wvy', 'toe_wvz', 'foot_pitch' }
for _, n in ipairs(names) do head[#head + 1] = 'q_' .. n end
for _, n in ipairs(names) do head[#head + 1] = 'qd_' .. n end
for _, n in ipairs({ 'hip_pitch', 'knee', 'ank_pitch' }) do head[#head + 1] = 'sq_' .. n end
for _, n in ipairs({ 'hip_pitch', 'knee', 'ank_pitch' }) do head[#head + 1] = 'sqd_' .. n end
f:write(table.concat(head, ','), '\n')

local STATES = { stance = 0, kick_left = 1, kick_right = 1, falling = 2 }
Motion.request('kick_' .. side)
local t0 = Body.get_time()
local prev, prev_t
local peak_ball, peak_toe, toe_at_contact, t_contact = 0, 0, nil, nil
local fell = false
while Body.get_time() - t0 < 7 do
  wait(0.008)
  local r = Sim.truth()
  local t = Body.get_time() - t0
  local q6, qd6 = ks.leg(side), ks.leg(side, Body.get_velocity)
  local toe = ks.toe_in_torso(side, q6)
  local rv = ks.toe_velocity_in_torso(side, q6, qd6)
  -- toe in the field: torso origin + R(torso) * toe; its velocity: the torso origin's (truth,
  -- differenced) + R(torso) * (toe velocity from the joints + gyro x toe)
  local w = ks.rot(r.roll, r.pitch, r.yaw, toe)
  local tw = { r.x + w[1], r.y + w[2], r.z + w[3] }
  local g = Body.get_gyro()
  local vt = { rv[1] + g[2] * toe[3] - g[3] * toe[2], rv[2] + g[3] * toe[1] - g[1] * toe[3],
    rv[3] + g[1] * toe[2] - g[2] * toe[1] }
  local wv = ks.rot(r.roll, r.pitch, r.yaw, vt)
  local c, s = math.cos(r.yaw), math.sin(r.yaw)
  if prev then
    local dt = t - prev_t
    wv[1], wv[2], wv[3] = wv[1] + (r.x - prev[1]) / dt, wv[2] + (r.y - prev[2]) / dt, wv[3] + (r.z - prev[3]) / dt
  end
  local fwd = c * wv[1] + s * wv[2]
  local bvx, bvy = r.ball.vx, r.ball.vy
  local bs = math.sqrt(bvx * bvx + bvy * bvy)
  if bs > 0.05 and not t_contact then t_contact, toe_at_contact = t, fwd end
  if bs > peak_ball then peak_ball = bs end
  if fwd > peak_toe then peak_toe = fwd end
  fell = fell or r.fallen
  local row = { t, STATES[Motion.state()] or 3, r.x, r.y, r.z, r.roll, r.pitch, r.yaw, r.ball.x, r.ball.y,
    r.ball.z, bvx, bvy, toe[1], toe[2], toe[3], tw[3], rv[1], rv[3], fwd, -s * wv[1] + c * wv[2], wv[3],
    ks.foot_pitch(side, q6) + r.pitch }
  for k = 1, 6 do row[#row + 1] = q6[k] end
  for k = 1, 6 do row[#row + 1] = qd6[k] end
  for _, n in ipairs({ 'hip_pitch', 'knee', 'ank_pitch' }) do row[#row + 1] = Body.get_position(sup .. n) end
  for _, n in ipairs({ 'hip_pitch', 'knee', 'ank_pitch' }) do row[#row + 1] = Body.get_velocity(sup .. n) end
  for k = 1, #row do row[k] = string.format('%.5f', row[k]) end
  f:write(table.concat(row, ','), '\n')
  prev, prev_t = { r.x, r.y, r.z }, t
end
f:close()
local b1 = Sim.truth().ball
local d = math.sqrt((b1.x - b0.x) ^ 2 + (b1.y - b0.y) ^ 2)
print(string.format('# kick %s gap %.3f: ball travelled %.2f m; peak ball speed %.2f m/s; toe forward speed ' ..
  '%.2f m/s at first ball motion (t=%.3f), peak %.2f m/s; fallen %s, state %s', side, gap, d, peak_ball,
  toe_at_contact or 0, t_contact or -1, peak_toe, tostring(fell or Sim.truth().fallen), Motion.state()))
