-- Turning on the spot in the sim's lockstep, logged tick by tick (run by Tools/tune/turn_trace.sh):
--   ./run_repl Tools/tune/turn_trace.lua OUT.csv|- VA [SECONDS]
-- Walks at (0, 0, VA) for SECONDS (default 10) after a 3 s ramp. OUT.csv: time, the torso's truth
-- (yaw), each hip yaw's command and measured angle, each foot's yaw and position in the world (the
-- torso's truth composed with the measured leg's forward kinematics), the feet's vertical forces,
-- the walk's planned foot yaws (its ground frame) and its support foot. Figures: the measured
-- turning rate, the hip yaw's lag behind its command at the swing foot's touch-down, and the yaw
-- each foot slips while it carries (the change of its world yaw over its stance).
-- luacheck: globals Sim Motion Walk wait Body
package.path = os.getenv('HRP_ROOT') .. '/Tests/motion/?.lua;' .. package.path
if not Sim then Sim = require('sim_shim') end -- luacheck: ignore Sim
local ks = require('kick_setup')
local sc = require('Tests.scenario_lib').new(wait, Body)
local note = sc.note
local motion = ks.wait_for_motion(wait)
if not motion then print('not ok 1 - the motion process is not running') os.exit(1) end
local Config = require('Config')
local kin = require('kinematics')
local shm = require('shm')

local out, va, seconds = arg[1] or '-', tonumber(arg[2]) or 2.0, tonumber(arg[3]) or 10
ks.apply_walk_params(Walk, wait, note)
local robot = Config.load('robot')
local model = kin.load()
local sensor, actuator = shm.open('dcm.sensor'), shm.open('dcm.actuator')
local legi = { l = model.leg_index[0], r = model.leg_index[1] }
local function wrap(a) return (a + math.pi) % (2 * math.pi) - math.pi end
local cos, sin = math.cos, math.sin

-- a foot's yaw and ground position in the world: torso truth (yaw, pitch, roll) x leg FK
local q6, pose = {}, {}
local function foot_world(side, s)
  local idx = legi[side]
  for k = 1, 6 do q6[k] = sensor.position[idx[k] - 1] end
  model:leg_fk(side, q6, pose)
  -- R_torso = Rz(yaw) Ry(pitch) Rx(roll); the foot's x axis R_torso * R_foot * ex, projected
  local cy, sy, cp, sp, cr, sr = cos(s.yaw), sin(s.yaw), cos(s.pitch), sin(s.pitch), cos(s.roll), sin(s.roll)
  local function rot(x, y, z)
    local y1, z1 = cr * y - sr * z, sr * y + cr * z
    local x2, z2 = cp * x + sp * z1, -sp * x + cp * z1
    return cy * x2 - sy * y1, sy * x2 + cy * y1, z2
  end
  local fy, fp = pose[6], pose[5]
  local ax, ay = rot(cos(fy) * cos(fp), sin(fy) * cos(fp), -sin(fp))
  local px, py = rot(pose[1], pose[2], pose[3])
  return math.atan2(ay, ax), s.x + px, s.y + py
end

Sim.reset()
wait(0.2)
Sim.teleport_robot(0, 0, 0)
Sim.teleport_ball(4.0, -3.5)
wait(0.2)
Walk.set_velocity(0, 0, 0)
Motion.request('stand')
wait(2.5)
Motion.request('walk')
Walk.set_velocity(0, 0, va)
wait(3)
local csv
if out ~= '-' then
  csv = assert(io.open(out, 'w'))
  csv:write('t,yaw,lcmd,lpos,rcmd,rpos,lyaw,lx,ly,ryaw,rx,ry,fl,fr,pla,pra,steps\n')
end
local dt = robot.period
local t0 = Body.get_time()
local yaw, last = 0, Sim.truth().yaw
local fell = false
-- per foot: stance start yaw (while it carries), slips; touch-down lag of the hip yaw
local carry = { l = nil, r = nil }
local slips = { l = {}, r = {} }
local lags = {}
local mg = 0
local lhy, rhy = legi.l[1] - 1, legi.r[1] - 1
while Body.get_time() - t0 < seconds do
  local s = Sim.truth()
  yaw = yaw + wrap(s.yaw - last)
  last = s.yaw
  if s.fallen or Motion.state() ~= 'walk' then fell = true break end
  local lyaw, lx, ly = foot_world('l', s)
  local ryaw, rx, ry = foot_world('r', s)
  local fl, fr = sensor.foot_force[0], sensor.foot_force[1]
  mg = math.max(mg, fl + fr)
  local wf = motion.walk_feet
  if csv then
    csv:write(string.format('%.4f' .. string.rep(',%.5f', 15) .. ',%d\n', Body.get_time() - t0, s.yaw,
      actuator.command[lhy], sensor.position[lhy], actuator.command[rhy], sensor.position[rhy],
      lyaw, lx, ly, ryaw, rx, ry, fl, fr, wf[2], wf[5], motion.walk_steps[0]))
  end
  -- a foot carries above half the weight: its world yaw should stay; record the change per stance
  local feet = { l = { fl, lyaw, lhy }, r = { fr, ryaw, rhy } }
  for side, v in pairs(feet) do
    local loaded = v[1] > 0.5 * mg
    if loaded and not carry[side] then
      carry[side] = v[2]
      lags[#lags + 1] = actuator.command[v[3]] - sensor.position[v[3]]
    elseif not loaded and carry[side] then
      slips[side][#slips[side] + 1] = wrap(v[2] - carry[side])
      carry[side] = nil
    end
  end
  wait(dt)
end
if csv then csv:close() end
local dur = Body.get_time() - t0
local function stats(t)
  local n, sum, sabs = #t, 0, 0
  for _, x in ipairs(t) do sum, sabs = sum + x, sabs + math.abs(x) end
  return n, n > 0 and sum / n or 0, n > 0 and sabs / n or 0
end
local n, mean, mabs = stats(lags)
note('turn %.2f rad/s commanded: measured %.3f rad/s over %.1f s%s', va, yaw / dur, dur, fell and ' (FELL)' or '')
note('hip yaw command - measured at touch-down: mean %.3f rad, mean |.| %.3f rad (%d touch-downs)', mean, mabs, n)
for _, side in ipairs({ 'l', 'r' }) do
  local k, m, a = stats(slips[side])
  note('%s foot: yaw slip over a stance mean %.3f rad, mean |.| %.3f rad (%d stances)', side, m, a, k)
end
print(string.format('turn %.3f %.3f %s', va, yaw / dur, fell and 'fell' or 'ok'))
Walk.set_velocity(0, 0, 0)
