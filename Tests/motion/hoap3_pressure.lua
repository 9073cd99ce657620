-- Scenario of Tests/motion/hoap3_pressure_test.sh (./run_repl in lockstep, ROBOT=hoap3): the
-- HOAP-3's four pressure sensors under each foot (robot.lua foot_pressure, dcm.sensor.foot_pressure)
-- against the sim's truth (the centre of pressure of the ground's forces on the soles, Sim.truth().cop).
-- Standing: the sensors' centre of pressure (field frame, through the sole frames' true poses:
-- Tests/wbc/zmp_margin.lua) within a few mm of the truth's and inside the support polygon, and the
-- motion process's measured ZMP (Player/Motion/balance.lua on the same sensors, motion.zmp in the
-- walk's frame) the truth's relative to the feet's midpoint. Then the weight shifts sideways (both legs'
-- hip and ankle rolls taken from motion and turned in parallel: the torso moves over one foot) and
-- back: the centre of pressure follows, the sensors' with it. Writes LOG (one row a tick), prints
-- TAP and the figures.
--   hoap3_pressure.lua LOG.csv
-- luacheck: read globals Sim Body Motion wait
package.path = os.getenv('HRP_ROOT') .. '/Tests/wbc/?.lua;' .. package.path
local sc = require('Tests.scenario_lib').new(wait, Body)
local tap, note, wait_until = sc.tap, sc.note, sc.wait_until
local shm = require('shm')
local zmp_margin = require('zmp_margin')
local log = assert(arg[1], 'usage: hoap3_pressure.lua LOG.csv')

-- the bounds: standing, the sensors' centre of pressure within 3 mm of the truth's (the model gives
-- each foot's exactly inside its sensors' rectangle); leaning, within 6 mm (the foot that unloads
-- tips onto a sole's edge, where its sensors, 12.5 mm inside the edge, read their own: 4 mm on both
-- feet's); motion's ZMP the truth's relative to the feet's midpoint within 3 mm (it places the
-- sensors with the walk's feet, not the true ones); inside the soles by 5 mm (standing it is near
-- the middle of the stance); the shift moves it 10 mm or more
local AGREE, AGREE_LEAN, INSIDE, SHIFT, ROLL = 0.003, 0.006, 0.005, 0.010, 0.08

tap(wait_until(function() return Motion.state() == 'stance' end, 10), 'in stance')
wait(1.0)
local motion = shm.open('motion')
local zm = zmp_margin.new(Sim, shm)
local dt = Body.period()
local f = assert(io.open(log, 'w'))
f:write('t,phase,sens_x,sens_y,true_x,true_y,true_fz,margin,motion_dx,motion_dy,true_dx,true_dy\n')

-- one tick's figures: the sensors' and the truth's centres of pressure, the margin, and both relative
-- to the feet's midpoint (motion's in its walk frame, the truth's in the field)
local stats = {}
local function sample(phase)
  zm:feet()
  local m, sx, sy = zm:margin()
  local cop = Sim.truth().cop
  local ls, rs = Sim.link_truth('l_sole'), Sim.link_truth('r_sole')
  local z, u = motion.zmp, motion.walk_feet
  local function local_of(x, y, ox, oy, yaw)
    local c, s = math.cos(yaw), math.sin(yaw)
    return c * (x - ox) + s * (y - oy), -s * (x - ox) + c * (y - oy)
  end
  local mdx, mdy = local_of(z[0], z[1], 0.5 * (u[0] + u[3]), 0.5 * (u[1] + u[4]), 0.5 * (u[2] + u[5]))
  local tdx, tdy = local_of(cop.x, cop.y, 0.5 * (ls.x + rs.x), 0.5 * (ls.y + rs.y), 0.5 * (ls.yaw + rs.yaw))
  local st = stats[phase] or { n = 0, agree = 0, motion = 0, margin = math.huge, sx = 0, sy = 0, tx = 0, ty = 0 }
  stats[phase] = st
  if m and cop.fz > 0 and motion.zmp_contact[0] == 1 then
    st.n = st.n + 1
    st.agree = math.max(st.agree, math.sqrt((sx - cop.x) ^ 2 + (sy - cop.y) ^ 2))
    st.motion = math.max(st.motion, math.sqrt((mdx - tdx) ^ 2 + (mdy - tdy) ^ 2))
    st.margin = math.min(st.margin, m)
    st.sx, st.sy, st.tx, st.ty = sx, sy, cop.x, cop.y
  end
  f:write(string.format('%.3f,%s,%.6f,%.6f,%.6f,%.6f,%.3f,%.6f,%.6f,%.6f,%.6f,%.6f\n', Body.get_time(), phase,
    sx or 0 / 0, sy or 0 / 0, cop.x, cop.y, cop.fz, m or 0 / 0, mdx, mdy, tdx, tdy))
end
local function hold(phase, seconds)
  for _ = 1, math.floor(seconds / dt + 0.5) do wait(dt) sample(phase) end
end

hold('standing', 1.0)
-- the weight over one foot: both legs lean sideways in parallel (hip roll +a, ankle roll -a keeps
-- the soles flat), ramped over 1 s, held 1 s, and back
local rolls = { 'l_hip_roll', 'r_hip_roll', 'l_ank_roll', 'r_ank_roll' }
local q0 = {}
for _, j in ipairs(rolls) do q0[j] = Body.get_command(j) end
local function lean(a)
  for _, j in ipairs(rolls) do Body.set_command(j, q0[j] + (j:match('hip') and a or -a)) end
end
local torso0 = Sim.truth()
local ramp = math.floor(1.0 / dt + 0.5)
for k = 1, ramp do lean(ROLL * k / ramp) wait(dt) sample('leaning') end
hold('leaned', 1.0)
local torso1 = Sim.truth()
for k = ramp - 1, 0, -1 do lean(ROLL * k / ramp) wait(dt) sample('leaning') end
for _, j in ipairs(rolls) do Body.release(j) end
hold('back', 1.0)
f:close()

local s, l, b = stats.standing, stats.leaned, stats.back
for _, name in ipairs({ 'standing', 'leaning', 'leaned', 'back' }) do
  local st = stats[name]
  note('%s: %d ticks; sensors against truth at most %.2f mm apart, motion\'s measured ZMP %.2f mm; smallest margin '
    .. 'inside the support polygon %.1f mm; last: sensors (%.4f, %.4f), truth (%.4f, %.4f) m', name, st.n,
    st.agree * 1e3, st.motion * 1e3, st.margin * 1e3, st.sx, st.sy, st.tx, st.ty)
end
tap(s.n > 0 and s.agree < AGREE, string.format("standing: the sensors' centre of pressure within %.0f mm of the "
  .. "truth's (%.2f mm)", AGREE * 1e3, s.agree * 1e3))
tap(s.n > 0 and s.motion < AGREE, string.format("standing: motion's measured ZMP within %.0f mm of the truth's, "
  .. "relative to the feet's midpoint (%.2f mm)", AGREE * 1e3, s.motion * 1e3))
tap(s.margin > INSIDE, string.format('standing: inside the support polygon by more than %.0f mm (%.1f mm)',
  INSIDE * 1e3, s.margin * 1e3))
local moved, torso = l.ty - s.ty, torso1.y - torso0.y
note('leaning %.2f rad: the torso moved %.1f mm sideways, the centre of pressure %.1f mm (truth), %.1f mm (sensors)',
  ROLL, torso * 1e3, moved * 1e3, (l.sy - s.sy) * 1e3)
tap(math.abs(moved) > SHIFT and moved * torso > 0 and math.abs((l.sy - s.sy) - moved) < AGREE,
  string.format('shifting the weight moves the centre of pressure with the torso by more than %.0f mm, the sensors '
  .. 'with it (%.1f mm)', SHIFT * 1e3, (l.sy - s.sy) * 1e3))
tap(l.agree < AGREE_LEAN and stats.leaning.agree < AGREE_LEAN and b.agree < AGREE_LEAN,
  string.format("leaning, leaned and back: the sensors' centre of pressure within %.0f mm of the truth's (%.2f, %.2f, "
  .. '%.2f mm)', AGREE_LEAN * 1e3, stats.leaning.agree * 1e3, l.agree * 1e3, b.agree * 1e3))
tap(not Sim.truth().fallen and Motion.state() == 'stance', 'standing at the end: ' .. Motion.state())
