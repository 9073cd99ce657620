-- The robot's body: joints by name or index, commands and sensors through shm, radians everywhere.
--
-- Joint names, order, groups and limits come from the body's robot.lua (Config/robots/<ROBOT>/). A command beyond
-- a joint's limit is clamped (counted in body.stats.clamped); a NaN or infinite command is refused
-- (counted in body.stats.refused) and never reaches dcm.actuator.
--
-- Commands and the motion process (Player/Motion): motion drives the joints its current state
-- owns and holds the others (Motion.owners() tells which). A command through Body for a joint
-- motion drives (set_command, set_commands, set_head_command ...) takes that joint from motion:
-- motion then writes the caller's command for it (motion.taken / taken_command) until
-- Body.release(group or joint) or a motion request whose state needs it (Motion.request('walk')
-- takes the head back for behavior). A joint motion holds is simply commanded. Hardness is not
-- taken: set it on a joint motion holds, or after the command that takes it.
--
-- Torque mode (dcm.actuator.mode and torque; docs/whole-body.md, Torque mode): Body.set_torque(joint,
-- N*m) puts a joint in torque mode with that torque and takes it from motion, which leaves a joint in
-- torque mode alone; Body.set_mode(joint, 'position') (or Body.release) puts it back in position
-- mode holding where it is. The DCM clamps a torque to the joint's actuator limit
-- (dcm.stats.torque_clamped) and on a watchdog trip puts every joint back in position mode.
local shm = require('shm')
local Config = require('Config')

local M = {}

local robot = Config.load('robot', { joints = 'table', groups = 'table', limits = 'table', period = 'number' })
local robot_file = table.concat(Config.files('robot'), ' + ')
local sensor = shm.open('dcm.sensor')
local actuator = shm.open('dcm.actuator')
local stats = shm.open('body.stats')
local motion = shm.lazy('motion')

local names = {}
local index = {}
local lo, hi = {}, {}
for i, name in ipairs(robot.joints) do
  names[i] = name
  index[name] = i
  local lim = rawget(robot.limits, name)
  if type(lim) ~= 'table' or type(lim[1]) ~= 'number' or type(lim[2]) ~= 'number' or lim[1] > lim[2] then
    error(string.format("%s: key 'limits.%s' must be { min, max } in radians", robot_file, name), 0)
  end
  lo[i], hi[i] = lim[1], lim[2]
end
local njoint = #names
if njoint > actuator:count('command') then
  error(string.format("%s: %d joints but the shm schema has room for %d (const njoint)",
    robot_file, njoint, actuator:count('command')), 0)
end

local groups = {}
for gname, members in pairs(robot.groups) do
  local idx = {}
  for k, jname in ipairs(members) do
    idx[k] = index[jname] or error(string.format(
      "%s: group '%s' names unknown joint '%s'", robot_file, gname, jname), 0)
  end
  groups[gname] = idx
end

local command, hardness, torque = actuator.command, actuator.hardness, actuator.torque_enable
local mode, joint_torque = actuator.mode, actuator.torque
local MODES = { position = 0, torque = 1 }
local position, velocity, load = sensor.position, sensor.velocity, sensor.load

local function finite(x)
  return type(x) == 'number' and x == x and x ~= math.huge and x ~= -math.huge
end

-- 1-based index of a joint given by name or index; errors on an unknown joint.
function M.index(joint)
  local i = type(joint) == 'number' and joint or index[joint]
  if not i or i < 1 or i > njoint or i % 1 ~= 0 then error("Body: unknown joint '" .. tostring(joint) .. "'", 3) end
  return i
end
local joint_index = M.index

function M.joint_names()
  local t = {}
  for i = 1, njoint do t[i] = names[i] end
  return t
end
function M.njoint() return njoint end
function M.limits(joint) local i = joint_index(joint) return lo[i], hi[i] end
function M.group(name)
  local g = groups[name] or error("Body: unknown joint group '" .. tostring(name) .. "'", 2)
  local t = {}
  for k, i in ipairs(g) do t[k] = names[i] end
  return t
end

-- Stores a checked command (clamped, NaN refused); returns false if refused. take: a caller's
-- command, which takes the joint from the motion process while motion drives it.
local function put_command(i, rad, take)
  if not finite(rad) then
    stats.refused[0] = stats.refused[0] + 1
    return false
  end
  if rad < lo[i] then rad = lo[i]; stats.clamped[0] = stats.clamped[0] + 1
  elseif rad > hi[i] then rad = hi[i]; stats.clamped[0] = stats.clamped[0] + 1 end
  if take then
    local m = motion()
    if m.owner[i - 1] ~= 0 or m.taken[i - 1] ~= 0 then
      m:write(function(b) b.taken_command[i - 1], b.taken[i - 1] = rad, 1 end)
    end
  end
  command[i - 1] = rad
  return true
end

function M.set_command(joint, rad) return put_command(joint_index(joint), rad, true) end
-- The motion process's own command: does not take the joint (see the header).
function M.drive(joint, rad) return put_command(joint_index(joint), rad, false) end
function M.get_command(joint) return command[joint_index(joint) - 1] end
function M.get_position(joint) return position[joint_index(joint) - 1] end
function M.get_velocity(joint) return velocity[joint_index(joint) - 1] end
function M.get_load(joint) return load[joint_index(joint) - 1] end

-- Hardness 0..1 (fraction of the servo's torque limit); NaN refused, out of range clamped.
function M.set_hardness(joint, h)
  local i = joint_index(joint)
  if not finite(h) then stats.refused[0] = stats.refused[0] + 1 return false end
  hardness[i - 1] = math.max(0, math.min(1, h))
  return true
end
function M.get_hardness(joint) return hardness[joint_index(joint) - 1] end
function M.set_torque_enable(joint, on) torque[joint_index(joint) - 1] = on and 1 or 0 end

-- All joints at once: tables in joint order (1-based).
function M.set_commands(t)
  local ok = true
  for i = 1, njoint do if t[i] ~= nil then ok = put_command(i, t[i], true) and ok end end
  return ok
end
function M.get_commands() local t = {} for i = 1, njoint do t[i] = command[i - 1] end return t end
function M.get_positions() local t = {} for i = 1, njoint do t[i] = position[i - 1] end return t end
function M.set_all_hardness(h) for i = 1, njoint do M.set_hardness(i, h) end end
function M.set_all_torque_enable(on) for i = 1, njoint do torque[i - 1] = on and 1 or 0 end end

local function group_setter(gname)
  local g = groups[gname]
  return function(values)
    if not g then error("Body: this robot has no joint group '" .. gname .. "'", 2) end
    local ok = true
    for k, i in ipairs(g) do
      if values[k] ~= nil then ok = put_command(i, values[k], true) and ok end
    end
    return ok
  end
end
local function group_getter(gname, array)
  local g = groups[gname]
  return function()
    if not g then error("Body: this robot has no joint group '" .. gname .. "'", 2) end
    local t = {}
    for k, i in ipairs(g) do t[k] = array[i - 1] end
    return t
  end
end
local function group_hardness(gname)
  return function(h)
    local g = groups[gname] or error("Body: this robot has no joint group '" .. gname .. "'", 2)
    for _, i in ipairs(g) do M.set_hardness(i, h) end
  end
end

M.set_head_command = group_setter('head')
M.set_larm_command = group_setter('larm')
M.set_rarm_command = group_setter('rarm')
M.set_lleg_command = group_setter('lleg')
M.set_rleg_command = group_setter('rleg')
M.get_head_command = group_getter('head', command)
M.get_larm_command = group_getter('larm', command)
M.get_rarm_command = group_getter('rarm', command)
M.get_lleg_command = group_getter('lleg', command)
M.get_rleg_command = group_getter('rleg', command)
M.get_head_position = group_getter('head', position)
M.get_larm_position = group_getter('larm', position)
M.get_rarm_position = group_getter('rarm', position)
M.get_lleg_position = group_getter('lleg', position)
M.get_rleg_position = group_getter('rleg', position)
M.set_head_hardness = group_hardness('head')
M.set_larm_hardness = group_hardness('larm')
M.set_rarm_hardness = group_hardness('rarm')
M.set_lleg_hardness = group_hardness('lleg')
M.set_rleg_hardness = group_hardness('rleg')

-- Torque mode. set_torque(joint, nm): the joint in torque mode with nm N*m (taken from motion; the
-- DCM clamps to the actuator's limit); a NaN or infinite torque is refused: returns false and a
-- message naming the joint, and nothing changes (counted in body.stats.refused).
function M.set_torque(joint, nm)
  local i = joint_index(joint)
  if not finite(nm) then
    stats.refused[0] = stats.refused[0] + 1
    return false, string.format("Body.set_torque: the torque for joint '%s' must be a finite number of N*m, not %s",
      names[i], tostring(nm))
  end
  if mode[i - 1] == 0 then put_command(i, position[i - 1], true) end   -- taken, holding here on a return
  actuator:write(function(a) a.torque[i - 1], a.mode[i - 1] = nm, 1 end)
  return true
end
function M.get_torque(joint) return joint_torque[joint_index(joint) - 1] end
-- The motion process's own torque (does not take the joint, as drive): nm N*m in torque mode, or nil:
-- back to position mode holding where the joint is. A NaN or infinite torque is refused as set_torque's.
function M.drive_torque(joint, nm)
  local i = joint_index(joint)
  if nm == nil then
    if mode[i - 1] ~= 0 then
      put_command(i, position[i - 1], false)
      actuator:write(function(a) a.mode[i - 1], a.torque[i - 1] = 0, 0 end)
    end
    return true
  end
  if not finite(nm) then
    stats.refused[0] = stats.refused[0] + 1
    return false, string.format("Body.drive_torque: the torque for joint '%s' must be a finite number of N*m, not %s",
      names[i], tostring(nm))
  end
  if mode[i - 1] == 0 then put_command(i, position[i - 1], false) end   -- held here on a return
  actuator:write(function(a) a.torque[i - 1], a.mode[i - 1] = nm, 1 end)
  return true
end

-- set_mode(joint, 'position' | 'torque'): 'position' holds the joint where it is now; 'torque' applies
-- the torque the block holds (0 unless set_torque gave one). get_mode(joint) says which.
function M.set_mode(joint, name)
  local i = joint_index(joint)
  local m = MODES[name]
  if not m then
    error(string.format("Body.set_mode: joint '%s': mode 'position' or 'torque' expected, got %s", names[i],
      tostring(name)), 2)
  end
  if m == 0 then
    if mode[i - 1] ~= 0 then
      put_command(i, position[i - 1], true)
      actuator:write(function(a) a.mode[i - 1], a.torque[i - 1] = 0, 0 end)
    end
    return true
  end
  return M.set_torque(i, joint_torque[i - 1])
end
function M.get_mode(joint) return mode[joint_index(joint) - 1] == 1 and 'torque' or 'position' end

-- Gives joints taken by a caller back to the motion process: a group name ('head'), a joint (name
-- or index), or nil for every joint; a joint in torque mode goes back to position mode first.
function M.release(what)
  local list
  if what == nil then
    list = {}
    for i = 1, njoint do list[i] = i end
  elseif type(what) == 'string' and groups[what] then
    list = groups[what]
  else
    list = { joint_index(what) }
  end
  for _, i in ipairs(list) do M.set_mode(i, 'position') end
  motion():write(function(b) for _, i in ipairs(list) do b.taken[i - 1] = 0 end end)
end
-- True while a caller holds the joint (name or index) taken from the motion process.
function M.taken(joint) return motion().taken[joint_index(joint) - 1] ~= 0 end

-- Sensors.
local function vec3(p) return { p[0], p[1], p[2] } end
function M.get_gyro() return vec3(sensor.gyro) end                   -- rad/s, torso frame
function M.get_accelerometer() return vec3(sensor.accelerometer) end -- m/s^2, with gravity
function M.get_angle() return vec3(sensor.angle) end                 -- roll, pitch, yaw (rad)
function M.get_foot_force() return { sensor.foot_force[0], sensor.foot_force[1] } end
-- N, the point pressure sensors under the soles (robot.lua foot_pressure): the left foot's, then the
-- right's; {} on a body without them
local npressure = 0
do
  local fp = rawget(robot, 'foot_pressure')
  if fp then npressure = #fp.lfoot.points + #fp.rfoot.points end
end
function M.get_foot_pressure()
  local t = {}
  for k = 1, npressure do t[k] = sensor.foot_pressure[k - 1] end
  return t
end
function M.get_button(k) return sensor.button[(k or 1) - 1] end
function M.get_battery() return sensor.battery[0] end
-- The robot's clock (simulated time under the sim): the only clock robot code uses.
function M.get_time() return sensor.time[0] end
function M.get_tick() return sensor.tick[0] end
function M.period() return robot.period end

-- Consistent snapshot of time and tick.
function M.get_time_tick()
  return sensor:read(function(s) return s.time[0], s.tick[0] end)
end

-- Waits until the DCM has published a tick other than `last_tick`; returns the new tick, or nil
-- after `timeout` seconds of wall time with no DCM progress.
function M.wait_tick(last_tick, timeout)
  local deadline = shm.C.shm_now() + (timeout or 1.0)
  local last_writes = 0
  while true do
    local t = sensor.tick[0]
    if t ~= last_tick then return t end
    local left = deadline - shm.C.shm_now()
    if left <= 0 then return nil end
    last_writes = sensor:wait_write(last_writes, math.min(left, 0.05))
  end
end

-- Blocks and statistics, for tools and tests.
M.sensor, M.actuator, M.stats = sensor, actuator, stats

return M
