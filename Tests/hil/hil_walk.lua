-- Walks the motion process of this robot (ROBOT_ID, any platform) forward (or keeps it standing:
-- VX = stand; or STAND seconds standing first, then SECONDS walking) and measures the simulated
-- robot behind it, robot SIM_ID of a sim DCM (the same id when the sim DCM serves this robot
-- directly; another when a bus emulator stands between them): no fall (from the sim's truth), the
-- distance, and the leg joints' tracking error, this robot's command (dcm.actuator) against the
-- simulated joint position (SIM_ID's dcm.sensor), sampled every 0.05 s: overall and per joint
-- group (hip yaw, hip roll, ... of both legs), and the ZMP error the motion process measures on the
-- feet's F/T sensors (motion.zmp; on a body with them).
-- Once the robot stands (stance), the sim is reset: the simulated robot upright at its start, joints
-- at their commands, whatever the start-up did to it (a DCM's watchdog holding it soft).
--   ./run_repl Tests/hil/hil_walk.lua [SECONDS [VX|stand [STAND]]]   (env SIM_ID)
-- Prints TAP lines and "# " figures, and for the caller a line "tracking RMS MAX" per phase
-- ("tracking stand RMS MAX" and "tracking walk RMS MAX" when it stood first).
-- luacheck: globals Motion Walk wait Body
local shm = require('shm')
local seconds = tonumber(arg[1]) or 30
local standing = arg[2] == 'stand'
local vx = standing and 0 or tonumber(arg[2]) or 0.2
local stand_first = not standing and tonumber(arg[3]) or nil
local sim_id = tonumber(os.getenv('SIM_ID') or '')
local sc = require('Tests.scenario_lib').new(wait, Body)
local tap, wait_until = sc.tap, sc.wait_until
if not sim_id then
  tap(false, 'hil_walk: SIM_ID (the sim DCM robot id) is not set')
  os.exit(1)
end
local Sim = require('Sim')
Sim.use_robot(sim_id)
local sim_sensor = shm.open('dcm.sensor', { robot = sim_id })
local sim_stats = shm.open('dcm.stats', { robot = sim_id })
local actuator = shm.open('dcm.actuator')
local truth = Sim.truth

-- the leg joints (robot.lua's groups lleg, rleg), shm indices; group k = the k-th joint of each leg
local legs, group_of = {}, {}
local robot = require('Config').load('robot')
local GROUPS = { 'hip yaw', 'hip roll', 'hip pitch', 'knee', 'ankle pitch', 'ankle roll' }
for _, g in ipairs({ 'lleg', 'rleg' }) do
  for k, name in ipairs(robot.groups[g]) do
    legs[#legs + 1] = Body.index(name) - 1
    group_of[#legs] = k
  end
end

-- the motion process runs and stands
local motion = shm.open('motion')
tap(wait_until(function() return motion.tick[0] ~= 0 end, 30), 'the motion process runs')
Walk.set_velocity(0, 0, 0)
Motion.request('stand')
tap(wait_until(function() return Motion.state() == 'stance' end, 15), 'stands (stance)')
wait(1.5)
-- (asked again once: on a loaded machine the real-time sim DCM may miss Sim's 2 s of wall time)
tap(Sim.reset() or Sim.reset(), 'the simulated robot is reset upright at its commands')
wait(1.0)

-- One phase: SECS of standing or walking at VX; returns false when the robot fell.
local function phase(name, secs, v)
  local walking = v ~= nil
  if walking then
    Motion.request('walk')
    Walk.set_velocity(v, 0, 0)
    wait(2)
  end
  local a = truth()
  local fell = false
  local sum2, nsamp, emax, rtf_min = 0, 0, 0, math.huge
  local gsum2, gn = {}, {}
  local zn, zx, zy = 0, 0, 0 -- ZMP error (motion.zmp: the feet's F/T against the walk's reference)
  for k = 1, #GROUPS do gsum2[k], gn[k] = 0, 0 end
  local t0 = Body.get_time()
  while Body.get_time() - t0 < secs do
    wait(0.05)
    local cmd, pos = {}, {}
    for k, j in ipairs(legs) do cmd[k] = actuator.command[j] end
    sim_sensor:read(function(x) for k, j in ipairs(legs) do pos[k] = x.position[j] end end)
    for k = 1, #legs do
      local e = math.abs(cmd[k] - pos[k])
      sum2 = sum2 + e * e
      nsamp = nsamp + 1
      local g = group_of[k]
      gsum2[g], gn[g] = gsum2[g] + e * e, gn[g] + 1
      if e > emax then emax = e end
    end
    if motion.zmp_contact[0] == 1 then
      local ex, ey = motion.zmp[0] - motion.zmp[2], motion.zmp[1] - motion.zmp[3]
      zn, zx, zy = zn + 1, zx + ex * ex, zy + ey * ey
    end
    local rtf = sim_stats.realtime_factor[0]
    if rtf > 0 and rtf < rtf_min then rtf_min = rtf end
    local s = truth()
    if s.fallen or Motion.state() ~= (walking and 'walk' or 'stance') then fell = true break end
  end
  local b = truth()
  local dt = Body.get_time() - t0
  local c, s = math.cos(a.yaw), math.sin(a.yaw)
  local speed = (c * (b.x - a.x) + s * (b.y - a.y)) / dt
  local rms = math.sqrt(sum2 / math.max(nsamp, 1))
  print(string.format('# %s %.1f s at %.2f m/s commanded: %.3f m/s measured; '
    .. 'leg tracking error RMS %.4f rad, max %.4f rad', walking and 'walked' or 'stood', dt, v or 0, speed, rms, emax))
  local per = {}
  for k, g in ipairs(GROUPS) do per[k] = string.format('%s %.4f', g, math.sqrt(gsum2[k] / math.max(gn[k], 1))) end
  print('# ' .. name .. ' leg tracking RMS per joint group (rad): ' .. table.concat(per, ', '))
  if zn > 0 then
    print(string.format('# %s ZMP error (the feet\'s F/T against the walk\'s reference) RMS x %.1f mm, y %.1f mm',
      name, 1000 * math.sqrt(zx / zn), 1000 * math.sqrt(zy / zn)))
  end
  print(string.format('# the sim DCM kept %.2f x real time at least (dcm.stats.realtime_factor, 1 s windows)', rtf_min))
  print(string.format('tracking%s %.5f %.5f', stand_first and ' ' .. name or '', rms, emax))
  if walking then
    tap(not fell, string.format('walks %d s without a fall', secs))
    tap(speed > 0.5 * v, string.format('moves forward (%.3f m/s)', speed))
  else
    local moved = math.sqrt((b.x - a.x) ^ 2 + (b.y - a.y) ^ 2)
    tap(not fell, string.format('stands %d s without a fall (moved %.4f m)', secs, moved))
  end
  return not fell
end

if standing then
  phase('stand', seconds)
elseif stand_first then
  if phase('stand', stand_first) then phase('walk', seconds, vx) end
else
  phase('walk', seconds, vx)
end
Walk.set_velocity(0, 0, 0)
Motion.request('stand')
