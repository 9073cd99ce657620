-- A walk pattern generated ahead (Tools/pattern/gen_pattern.lua) played by the motion state
-- `pattern` in the sim's lockstep, run by ./run_repl (see hoap3_pattern_test.sh):
--   ./run_repl Tests/motion/pattern_scenario.lua PATTERN.csv LOG.csv
-- Refuses a file with a NaN and one with another joint count (the error names file and line);
-- plays PATTERN from stance; checks no fall, the whole file played, back in stance, the distance
-- walked; prints the planned against measured ZMP (RMS, max) and joint angles (RMS per leg joint).
-- Measured: the joint angles the sim senses (dcm.sensor.position); the ZMP from the feet's sensors
-- the sim gives this body (dcm.sensor.foot_pressure: point pressure sensors under the soles,
-- robot.lua's `foot_pressure`, or else dcm.sensor.ft: 6-axis force/torque at each ankle, its `ft`),
-- through Player/Motion/balance.lua's measure() with the soles' poses from the sim's truth
-- (Sim.link_truth), in the pattern's frame (its origin midway between the soles at the file's
-- t = 0, x along their mean heading). LOG: one row a tick while the file plays.
-- luacheck: globals Sim Motion wait arg Body
local file, log = arg[1], arg[2]
local sc = require('Tests.scenario_lib').new(wait, Body)
local tap, note, wait_until = sc.tap, sc.note, sc.wait_until
local shm = require('shm')
local Config = require('Config')
local trajectory = require('trajectory')
local balance = require('Motion.balance')

local robot = Config.load('robot')
local wp = Config.load('walk')
local n = #robot.joints
local dt = robot.period
local sensor = shm.open('dcm.sensor')
local deg = 180 / math.pi
-- the bounds of the checks below (the figures they bound: docs/results/motion.md): the ZMP's RMS
-- error within the soles' half-width (0.0365 m on the HOAP-3), less a margin; each leg joint within
-- 3 deg RMS of its plan (the HOAP-3's 0.4 s steps, its knees asked for 7.5 of their 4 rad/s, are
-- 4.3 deg off)
local ZMP_RMS_MAX, JOINT_RMS_MAX = 0.030, 3 / deg

local tr = trajectory.load(file, robot)
local ji = {}
for i, name in ipairs(robot.joints) do ji[name] = i end

-- the plan's joint speeds against the drives' (Config actuators): open loop, a joint asked to move
-- faster than its drive falls behind its plan
local actuators = Config.load('actuators')
local fastest, fname = 0, ''
for k = 2, #tr.t do
  local h = tr.t[k] - tr.t[k - 1]
  for i, name in ipairs(robot.joints) do
    local f = math.abs(tr.q[k][i] - tr.q[k - 1][i]) / h / actuators[robot.actuator[name]].speed
    if f > fastest then fastest, fname = f, name end
  end
end
tap(fastest <= 1, string.format("the plan's joint speeds within the drives' (fastest: %s at %.0f%% of its drive's)",
  fname, 100 * fastest))

Motion.request('stand')
tap(wait_until(function() return Motion.state() == 'stance' end, 10), 'stance before the pattern')
wait(2)

-- bad files are refused at the request, naming the file and the line
local dir = log:match('^(.*)/[^/]*$') or '.'
local lines = {}
for line in io.lines(file) do lines[#lines + 1] = line end
local function write(name, edit)
  local path = dir .. '/' .. name
  local f = assert(io.open(path, 'w'))
  for k, line in ipairs(lines) do f:write(edit(k, line) or line, '\n') end
  f:close()
  return path
end
local header_line
for k, line in ipairs(lines) do if line:match('^t,') then header_line = k break end end
local nan_line = header_line + 5
local bad_nan = write('pattern_nan.csv', function(k, line)
  if k == nan_line then return (line:gsub(',[^,]*', ',nan', 1)) end
end)
local ok_nan, err_nan = pcall(Motion.request, 'pattern', { file = bad_nan })
tap(not ok_nan and tostring(err_nan):find('pattern_nan.csv:' .. nan_line .. ':', 1, true) ~= nil,
  'a file with a NaN is refused naming its line: ' .. tostring(err_nan))
local bad_count = write('pattern_count.csv', function(_, line)
  local c = line:match('^# joints (%d+)$')
  if c then return '# joints ' .. (tonumber(c) - 1) end
end)
local ok_count, err_count = pcall(Motion.request, 'pattern', { file = bad_count })
tap(not ok_count and tostring(err_count):find('pattern_count.csv:' .. header_line .. ':', 1, true) ~= nil,
  'a file with another joint count is refused naming its line: ' .. tostring(err_count))
wait(0.2)
tap(Motion.state() == 'stance', 'still in stance after the refusals')

-- play
local falls0 = Motion.falls()
local ft, press, meas = {}, {}, balance.new(wp, robot)
local origin -- the pattern's frame in the field: x, y, yaw
local function to_plan(x, y)
  local c, s = math.cos(origin[3]), math.sin(origin[3])
  local dx, dy = x - origin[1], y - origin[2]
  return c * dx + s * dy, -s * dx + c * dy
end
local function sole(name)
  local p = assert(Sim.link_truth(name))
  return p
end
Motion.request('pattern', { file = file })
local t_start = Body.get_time()
local seen_pattern, fell, t_end, pt_max = false, false, nil, -1
local e2, emax, ne = 0, 0, 0
local je2, jn = {}, 0
local legs = {}
for _, side in ipairs({ 'l', 'r' }) do
  for _, j in ipairs({ 'hip_yaw', 'hip_roll', 'hip_pitch', 'knee', 'ank_pitch', 'ank_roll' }) do
    legs[#legs + 1] = side .. '_' .. j
    je2[#legs] = 0
  end
end
local qp, pos = {}, {}
local f = assert(io.open(log, 'w'))
local head = { 't', 'pt', 'zmp_x', 'zmp_y', 'meas_x', 'meas_y', 'contact', 'lsole_x', 'lsole_y', 'rsole_x', 'rsole_y',
  'lfoot_x', 'lfoot_y', 'rfoot_x', 'rfoot_y', 'fz_l', 'fz_r', 'cop_x', 'cop_y', 'cop_fz' }
for _, j in ipairs(legs) do head[#head + 1] = 'plan_' .. j end
for _, j in ipairs(legs) do head[#head + 1] = 'meas_' .. j end
f:write(table.concat(head, ','), '\n')
while Body.get_time() - t_start < tr.duration + 15 do
  wait(dt)
  local state = Motion.state()
  if state == 'falling' or Sim.truth().fallen or Motion.falls() ~= falls0 then fell = true break end
  local pt = Motion.pattern_time()
  if state == 'pattern' then seen_pattern = true end
  if seen_pattern and state ~= 'pattern' then
    t_end = t_end or Body.get_time()
    if Body.get_time() - t_end > 1.0 then break end
  end
  if pt and pt >= 0 and state == 'pattern' then
    pt_max = math.max(pt_max, pt)
    local l, r = sole('l_sole'), sole('r_sole')
    if not origin then
      local a = l.yaw + 0.5 * (((r.yaw - l.yaw) + math.pi) % (2 * math.pi) - math.pi)
      -- the planned feet at t = 0 are at +-footY about the origin: the midpoint of the soles is it
      origin = { 0.5 * (l.x + r.x), 0.5 * (l.y + r.y), a }
    end
    for k = 1, 24 do ft[k] = sensor.ft[k - 1] end
    for k = 1, 8 do press[k] = sensor.foot_pressure[k - 1] end
    for i = 1, n do pos[i] = sensor.position[i - 1] end
    local lx, ly = to_plan(l.x, l.y)
    local rx, ry = to_plan(r.x, r.y)
    local contact = meas:measure(ft, { lx, ly, l.yaw - origin[3] }, { rx, ry, r.yaw - origin[3] }, press)
    -- the sim's truth: the centre of pressure of the ground's forces on the soles
    local cop = Sim.truth().cop
    local cx, cy = to_plan(cop.x, cop.y)
    local cf = cop.fz
    local zx, zy = tr:extra_at('zmp_x', pt), tr:extra_at('zmp_y', pt)
    local mx, my = meas.zmp[1], meas.zmp[2]
    if contact then
      local ex, ey = mx - zx, my - zy
      local e = math.sqrt(ex * ex + ey * ey)
      e2, emax, ne = e2 + e * e, math.max(emax, e), ne + 1
    end
    tr:joints_at(pt, qp)
    jn = jn + 1
    local row = { Body.get_time(), pt, zx, zy, contact and mx or 0 / 0, contact and my or 0 / 0, contact and 1 or 0,
      lx, ly, rx, ry, tr:extra_at('lfoot_x', pt), tr:extra_at('lfoot_y', pt), tr:extra_at('rfoot_x', pt),
      tr:extra_at('rfoot_y', pt), meas.force[1], meas.force[2], cf > 0 and cx or 0 / 0, cf > 0 and cy or 0 / 0, cf }
    for k, j in ipairs(legs) do
      local e = pos[ji[j]] - qp[ji[j]]
      je2[k] = je2[k] + e * e
      row[#row + 1] = qp[ji[j]]
    end
    for _, j in ipairs(legs) do row[#row + 1] = pos[ji[j]] end
    for k = 1, #row do row[k] = string.format('%.6g', row[k]) end
    f:write(table.concat(row, ','), '\n')
  end
end
f:close()

tap(not fell, string.format('no fall playing the pattern (%.1f s of %.1f s played)', math.max(pt_max, 0), tr.duration))
tap(pt_max >= tr.duration - 2 * dt, string.format('the whole file played (to %.3f s of %.3f s)', pt_max, tr.duration))
tap(not fell and wait_until(function() return Motion.state() == 'stance' end, 5), 'back in stance after it')
-- the distance: the soles' midpoint against the plan's last one
local last = #tr.t
local plan_x = 0.5 * (tr.extra.lfoot_x[last] + tr.extra.rfoot_x[last])
local got_x = 0
if origin then
  local l, r = sole('l_sole'), sole('r_sole')
  local lx = to_plan(l.x, l.y)
  local rx = to_plan(r.x, r.y)
  got_x = 0.5 * (lx + rx)
end
tap(not fell and got_x > 0.8 * plan_x and got_x < 1.2 * plan_x,
  string.format('walked %.3f m forward, planned %.3f m', got_x, plan_x))
local rms = ne > 0 and math.sqrt(e2 / ne) or math.huge
note('ZMP planned vs measured (%s, %d of %d ticks with a foot loaded): RMS %.1f mm, max %.1f mm',
  meas.pressure and 'foot pressure sensors' or 'ankle F/T', ne, jn, 1000 * rms, 1000 * emax)
tap(rms < ZMP_RMS_MAX, string.format('ZMP error RMS %.1f mm < %.0f mm', 1000 * rms, 1000 * ZMP_RMS_MAX))
local worst, wname = 0, ''
local parts = {}
for k, j in ipairs(legs) do
  local r = jn > 0 and math.sqrt(je2[k] / jn) or math.huge
  parts[#parts + 1] = string.format('%s %.2f', j, r * deg)
  if r > worst then worst, wname = r, j end
end
note('joint angles planned vs measured, RMS (deg): %s', table.concat(parts, ', '))
tap(worst < JOINT_RMS_MAX, string.format('every leg joint within %.1f deg RMS of the plan (worst %s %.2f deg)',
  JOINT_RMS_MAX * deg, wname, worst * deg))
os.exit(sc.count > 0 and 0 or 1)
