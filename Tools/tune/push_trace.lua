-- Sideways pushes on the walking robot in the sim's lockstep, logged tick by tick (run by
-- Tools/tune/push_trace.sh):
--   ./run_repl Tools/tune/push_trace.lua OUT.csv|- FORCES MOMENTS [GAIN]
-- FORCES: N for 0.1 s on the torso, to the robot's left (comma list); MOMENTS: when in the gait
-- cycle, k x tStep/2 after 3 s of walking at 0.2 m/s (comma list, 0..3, as the pushmax scenario);
-- GAIN: stepAdjust.gain for the run (default: the config's). For each force and moment: survived or
-- fell (how long after the push), the torso's turn since the push, and the step adjustment's counts.
-- OUT.csv (the last case): time, truth (x, y, yaw, roll, pitch), the walk's COM and feet (its ground
-- frame), the IMU's capture point error; the soles' truth (the torso's truth and the legs' forward
-- kinematics: x, y, z, roll, pitch (toe down), yaw) and the sim's vertical foot forces (N: an
-- instrument the real OP3 lacks).
-- luacheck: globals Sim Motion Walk wait Body
package.path = os.getenv('HRP_ROOT') .. '/Tests/motion/?.lua;' .. package.path
if not Sim then Sim = require('sim_shim') end -- luacheck: ignore Sim
local ks = require('kick_setup')
local sc = require('Tests.scenario_lib').new(wait, Body)
local note, wait_until = sc.note, sc.wait_until
local motion = ks.wait_for_motion(wait)
if not motion then print('not ok 1 - the motion process is not running') os.exit(1) end

local out = arg[1] or '-'
local forces, moments = {}, {}
for x in (arg[2] or '15'):gmatch('[^,]+') do forces[#forces + 1] = tonumber(x) end
for x in (arg[3] or '0'):gmatch('[^,]+') do moments[#moments + 1] = tonumber(x) end
-- WALK_PARAMS changes walk parameters first (e.g. to switch feedback off)
ks.apply_walk_params(Walk, wait)
if arg[4] then while not Walk.set('stepAdjust.gain', tonumber(arg[4])) do wait(0.01) end end

-- The soles' poses in the world from the sim's torso truth s and the legs' measured angles (forward
-- kinematics): { x, y, z, roll, pitch, yaw } of the left sole, .r the right's (whether a foot lies
-- flat, hangs in the air or turns on the ground after a push)
local model = require('kinematics').load()
local function sole(s, side)
  local f = model:leg_fk(side, ks.leg(side))
  local p = ks.to_world(s, { f[1], f[2], f[3] })
  local ex = ks.rot(s.roll, s.pitch, s.yaw, ks.rot(f[4], f[5], f[6], { 1, 0, 0 }))
  local ey = ks.rot(s.roll, s.pitch, s.yaw, ks.rot(f[4], f[5], f[6], { 0, 1, 0 }))
  return { p[1], p[2], p[3], math.asin(ey[3]), -math.asin(ex[3]), math.atan2(ex[2], ex[1]) }
end
local function feet_truth(s)
  local l = sole(s, 'left')
  l.r = sole(s, 'right')
  return l
end

local function one(f, k, csv)
  ks.fresh_stance(Sim, Motion, Walk, wait, wait_until, 'push_trace')   -- then as sim_scenarios.lua's pushmax
  Motion.request('walk')
  Walk.set_velocity(0.2, 0, 0)
  wait(3 + k * Walk.get('tStep') / 2)
  local a = Sim.truth()
  local falls0, adj0 = Motion.falls(), motion.steps_adjusted[0]
  local t0 = Body.get_time()
  Sim.push(-f * math.sin(a.yaw), f * math.cos(a.yaw), 0.1)
  -- fell: s after the push; yaw: the torso's turn since the push until then (a late fall follows a
  -- spin on the support foot)
  local fell, yaw = false, 0
  local dt = require('Config').load('robot').period
  while Body.get_time() - t0 < 3 do
    local s = Sim.truth()
    if csv then
      local wf, wc, e = motion.walk_feet, motion.walk_com, motion.capture_error
      local fmt = '%.4f' .. string.rep(',%.5f', 15) .. ','
      csv:write(string.format(fmt, Body.get_time() - t0, s.x, s.y, s.yaw, s.roll, s.pitch, wc[0], wc[1],
        wf[0], wf[1], wf[2], wf[3], wf[4], wf[5], e[0], e[1]))
      local l, ff = feet_truth(s), Body.get_foot_force()
      local r = l.r
      csv:write(string.format(string.rep('%.5f,', 12) .. '%.2f,%.2f\n', l[1], l[2], l[3], l[4], l[5], l[6],
        r[1], r[2], r[3], r[4], r[5], r[6], ff[1], ff[2]))
    end
    if not fell then yaw = (s.yaw - a.yaw + math.pi) % (2 * math.pi) - math.pi end
    if not fell and (s.fallen or Motion.falls() > falls0) then fell = Body.get_time() - t0 end
    if fell and not csv then break end
    wait(dt)
  end
  note('push %.1f N x 0.1 s at moment %d: %s, turned %.2f rad, landings moved %d', f, k,
    fell and string.format('FELL %.2f s after', fell) or 'survived', yaw, motion.steps_adjusted[0] - adj0)
  return not fell
end

for i, f in ipairs(forces) do
  local all = true
  for j, k in ipairs(moments) do
    local last = i == #forces and j == #moments
    local csv
    if last and out ~= '-' then
      csv = assert(io.open(out, 'w'))
      csv:write('t,x,y,yaw,roll,pitch,com_x,com_y,lx,ly,la,rx,ry,ra,cp_ex,cp_ey,' ..
        'lfx,lfy,lfz,lfroll,lfpitch,lfyaw,rfx,rfy,rfz,rfroll,rfpitch,rfyaw,ffl,ffr\n')
    end
    all = one(f, k, csv) and all
    if csv then csv:close() end
  end
  print(string.format('push %.1f %s', f, all and 'survived' or 'fell'))
end
Walk.set_velocity(0, 0, 0)
