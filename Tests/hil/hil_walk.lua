-- Walks the motion process of this robot (ROBOT_ID, any platform) forward and measures the
-- simulated robot behind it, robot SIM_ID of a sim DCM (the same id when the sim DCM serves this
-- robot directly; another when a bus emulator stands between them): no fall (from the sim's truth),
-- the distance, and the leg joints' tracking error, this robot's command (dcm.actuator) against the
-- simulated joint position (SIM_ID's dcm.sensor), sampled every 0.05 s of walking.
--   ./run_repl Tests/hil/hil_walk.lua [SECONDS [VX]]   (env SIM_ID)
-- Prints TAP lines and "# " figures, and a line "tracking RMS MAX" for the caller.
-- luacheck: globals Motion Walk wait Body
local shm = require('shm')
local seconds = tonumber(arg[1]) or 30
local vx = tonumber(arg[2]) or 0.2
local sim_id = tonumber(os.getenv('SIM_ID') or '')
local count = 0
local function tap(ok, msg)
  count = count + 1
  print(string.format('%s %d - %s', ok and 'ok' or 'not ok', count, msg))
  io.stdout:flush()
  return ok
end
if not sim_id then
  tap(false, 'hil_walk: SIM_ID (the sim DCM robot id) is not set')
  os.exit(1)
end
local truth_blk = shm.open('sim', { robot = sim_id })
local sim_sensor = shm.open('dcm.sensor', { robot = sim_id })
local actuator = shm.open('dcm.actuator')
local function truth()
  return truth_blk:read(function(x)
    return { x = x.robot[0], y = x.robot[1], yaw = x.robot[3], fallen = x.fallen[0] ~= 0 }
  end)
end

-- the leg joints (names starting l_ or r_ and holding hip, knee or ank), shm indices
local legs = {}
for i, name in ipairs(Body.joint_names()) do
  if name:match('^[lr]_') and (name:match('hip') or name:match('knee') or name:match('ank')) then
    legs[#legs + 1] = i - 1
  end
end

local function wait_until(pred, timeout)
  local t0 = Body.get_time()
  while Body.get_time() - t0 < timeout do
    if pred() then return true end
    wait(0.05)
  end
  return pred()
end

-- the motion process runs and stands
local motion = shm.open('motion')
tap(wait_until(function() return motion.tick[0] ~= 0 end, 30), 'the motion process runs')
Walk.set_velocity(0, 0, 0)
Motion.request('stand')
tap(wait_until(function() return Motion.state() == 'stance' end, 15), 'stands (stance)')
wait(1.5)

Motion.request('walk')
Walk.set_velocity(vx, 0, 0)
wait(2)
local a = truth()
local fell = false
local sum2, nsamp, emax = 0, 0, 0
local t0 = Body.get_time()
while Body.get_time() - t0 < seconds do
  wait(0.05)
  local cmd, pos = {}, {}
  for k, j in ipairs(legs) do cmd[k] = actuator.command[j] end
  sim_sensor:read(function(x) for k, j in ipairs(legs) do pos[k] = x.position[j] end end)
  for k = 1, #legs do
    local e = math.abs(cmd[k] - pos[k])
    sum2 = sum2 + e * e
    nsamp = nsamp + 1
    if e > emax then emax = e end
  end
  local s = truth()
  if s.fallen or Motion.state() ~= 'walk' then fell = true break end
end
local b = truth()
local dt = Body.get_time() - t0
local c, s = math.cos(a.yaw), math.sin(a.yaw)
local speed = (c * (b.x - a.x) + s * (b.y - a.y)) / dt
local rms = math.sqrt(sum2 / math.max(nsamp, 1))
print(string.format('# walked %.1f s at %.2f m/s commanded: %.3f m/s measured; '
  .. 'leg tracking error RMS %.4f rad, max %.4f rad', dt, vx, speed, rms, emax))
print(string.format('tracking %.5f %.5f', rms, emax))
tap(not fell, string.format('walks %d s without a fall', seconds))
tap(speed > 0.5 * vx, string.format('moves forward (%.3f m/s)', speed))
Walk.set_velocity(0, 0, 0)
Motion.request('stand')
