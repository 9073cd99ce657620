-- Walking over terrain in the sim's lockstep (Tests/motion/terrain_test.sh puts the layout's boxes
-- into the world through a site overlay: Tests/motion/terrain.lua):
--   ./run_repl Tests/motion/terrain_scenario.lua LAYOUT [fb|nofb]...
-- For each case: the robot from its start in front of the layout walks forward (0.15 m/s, or
-- TERRAIN_SPEED) over it
-- until it is past its far end: no fall, and it gets there within 40 s. `fb`: the walk's IMU
-- feedback as configured (the OP3 has no foot force sensors on the real robot, so its F/T balance
-- stays off: Config/robots/op3/walk.lua); `nofb`: the gyro feedback switched off as well (a figure
-- only, no TAP line: see below).
-- Prints TAP lines and "# " figures (the torso's height change tells the robot was up there);
-- VERBOSE=1: the truth and the walk's feet every 0.05 s.
-- luacheck: globals Sim Motion Walk wait Body
package.path = os.getenv('HRP_ROOT') .. '/Tests/motion/?.lua;' .. package.path
if not Sim then Sim = require('sim_shim') end -- luacheck: ignore Sim
local terrain = require('terrain')
local ks = require('kick_setup')
local sc = require('Tests.scenario_lib').new(wait, Body)
local tap, note, wait_until = sc.tap, sc.note, sc.wait_until

local layout_name = arg[1]
local SPEED = tonumber(os.getenv('TERRAIN_SPEED') or '') or 0.15 -- m/s forward
local layout = terrain[layout_name or '']
if type(layout) ~= 'table' or not layout.objects then
  tap(false, 'terrain: unknown layout ' .. tostring(layout_name))
  os.exit(1)
end
local motion = ks.need_motion(wait, tap)

-- WALK_PARAMS changes walk parameters first (e.g. to switch feedback off)
ks.apply_walk_params(Walk, wait, note)

-- the gyro feedback's gains as configured, and switched off
local FB = {}
for _, k in ipairs({ 'ankle', 'knee', 'hip', 'arm', 'tilt', 'capture', 'captureHip' }) do
  local v = Walk.get('feedback.' .. k)
  FB[k] = type(v) == 'table' and { v[1], v[2] } or v -- (nil: a body without that key)
end
local function feedback(on)
  for k, v in pairs(FB) do
    local off = type(v) == 'table' and { 0, 0 } or 0
    while not Walk.set('feedback.' .. k, on and v or off) do wait(0.01) end
  end
end

local function walk_over(mode)
  feedback(mode ~= 'nofb')
  Sim.reset()
  wait(0.2)
  Sim.teleport_robot(layout.start[1], layout.start[2], layout.start[3])
  wait(0.2)
  Walk.set_velocity(0, 0, 0)
  Motion.request('stand')
  wait_until(function() return Motion.state() == 'stance' end, 10)
  wait(1.5)
  local a = Sim.truth()
  local falls0 = Motion.falls()
  local t0 = Body.get_time()
  Motion.request('walk')
  Walk.set_velocity(SPEED, 0, 0)
  local fell, zmax, zmin = false, a.z, a.z
  -- TERRAIN_TRACE=file.csv: every tick of the walk (the last case run) for Tools/plot/plot_terrain.py
  local trace = os.getenv('TERRAIN_TRACE')
  local csv = trace and assert(io.open(trace, 'w'))
  if csv then csv:write('t,x,z,pitch,imu_pitch,gyro_y,lx,rx,lz_force,rz_force,cp_ex,com_x,odo_x\n') end
  local dt = require('Config').load('robot').period
  local arrived = wait_until(function()
    local s = Sim.truth()
    zmax, zmin = math.max(zmax, s.z), math.min(zmin, s.z)
    if os.getenv('VERBOSE') then
      local wf, o = motion.walk_feet, motion.odometry
      note('t %.2f truth x %.3f z %.3f pitch %.2f | walk: odometry x %.3f, feet x %.3f %.3f', Body.get_time() - t0,
        s.x, s.z, s.pitch, o[0], wf[0], wf[3])
    end
    if (s.fallen or Motion.falls() > falls0) and not fell then
      fell = true
      note('down %.2f s into the walk at x = %.3f: roll %.2f, pitch %.2f (truth fallen: %s)', Body.get_time() - t0,
        s.x, s.roll, s.pitch, tostring(s.fallen))
    end
    if csv then
      local wf, e, ang, g, ff = motion.walk_feet, motion.capture_error, Body.get_angle(), Body.get_gyro(),
        Body.get_foot_force()
      csv:write(string.format('%.3f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.2f,%.2f,%.4f,%.4f,%.4f\n',
        Body.get_time() - t0, s.x - a.x, s.z - a.z, s.pitch, ang[2], g[2], wf[0], wf[3], ff[1], ff[2], e[0],
        motion.walk_com[0], motion.odometry[0]))
    end
    return fell or s.x >= layout.finish
  end, 40, csv and dt or nil)
  if csv then csv:close() end
  local b = Sim.truth()
  Walk.set_velocity(0, 0, 0)
  Motion.request('stand')
  wait(1.5)
  fell = fell or Sim.truth().fallen or Motion.falls() > falls0
  note('terrain %s (%s): walked %.2f m in x, sideways %.2f m, the torso rose %.3f m at most (and sank %.3f m), %s',
    layout_name, mode, b.x - a.x, b.y - a.y, zmax - a.z, a.z - zmin, fell and 'FELL' or 'no fall')
  -- with the feedback off the figure is reported, not asserted: the OP3 gets over the ramp in some
  -- runs and not in others (a toe meeting the slope tips it back, as on the step)
  if mode == 'nofb' then return end
  tap(arrived and not fell, string.format(
    'terrain %s, feedback %s: walks over it without a fall (reached x = %.2f of %.2f)', layout_name,
    mode == 'nofb' and 'off' or 'on', b.x, layout.finish))
end

local modes = { select(2, unpack(arg)) }
if #modes == 0 then modes = { 'fb', 'nofb' } end
for _, m in ipairs(modes) do walk_over(m) end
feedback(true)
Walk.set_velocity(0, 0, 0)
