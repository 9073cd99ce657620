-- Kicks over ball placements in one sim (lockstep), one line of figures per kick:
--   ./run_repl Tests/motion/kick_sweep.lua SIDES GAPS LATERALS
-- SIDES: 'left,right'; GAPS: m from the toe to the ball's centre ('0.08,0.1,0.12'); LATERALS: m of
-- the ball's centre outward of the sole's centre ('-0.02,0,0.02'). Per kick: the ball's distance
-- and direction (from the robot's heading), its speed after contact and 0.3 s later (rolling),
-- the torso's largest tilt from upright, the capture point (COM + its velocity / sqrt(g / height))
-- against the support foot's ankle while the kick runs (forward range; inward on one foot), the
-- torso's yaw, falls counted by the motion process and the state at the end. Ends with a line
-- "sweep n=N min=D fallen=F".
-- luacheck: globals Sim Motion wait arg Body
if not Sim then
  package.path = os.getenv('HRP_ROOT') .. '/Tests/motion/?.lua;' .. package.path
  Sim = require('sim_shim')
end
package.path = os.getenv('HRP_ROOT') .. '/Tests/motion/?.lua;' .. package.path
local ks = require('kick_setup')
local shm = require('shm')

local function list(s, default)
  local t = {}
  for x in (s or default):gmatch('[^,]+') do t[#t + 1] = tonumber(x) or x end
  return t
end
local sides, gaps, lats = list(arg[1], 'left,right'), list(arg[2], '0.1'), list(arg[3], '0')

local motion = shm.open('motion')
for _ = 1, 300 do
  if motion.tick[0] ~= 0 and Body.get_tick() - motion.tick[0] <= 2 then break end
  wait(0.1)
end

local function wrap(a) return (a + math.pi) % (2 * math.pi) - math.pi end
local DT = 0.008

local function kick(side, gap, lat)
  local r0 = ks.setup(Sim, Motion, wait, side, gap, lat)
  local b0 = r0.ball
  local falls0 = motion.falls[0]
  Motion.request('kick_' .. side)
  local t0 = Body.get_time()
  local f = { tilt = 0, launch = 0, cp_max = -1, cp_min = 1, cp_in = -1, yaw = 0 }
  local kicking, t_contact, prev_com = true, nil, nil
  while Body.get_time() - t0 < 12 do
    wait(DT)
    local r = Sim.truth()
    local s = Motion.state()
    if kicking then
      f.tilt = math.max(f.tilt, math.abs(r.roll), math.abs(r.pitch - r0.pitch))
      f.yaw = math.max(f.yaw, math.abs(wrap(r.yaw - r0.yaw)))
      local com = ks.com_over_support(side, r)
      if prev_com then
        local w0 = math.sqrt(9.81 / math.max(0.1, com[3])) * DT
        local cf, ci = com[1] + (com[1] - prev_com[1]) / w0, com[2] + (com[2] - prev_com[2]) / w0
        f.cp_max, f.cp_min = math.max(f.cp_max, cf), math.min(f.cp_min, cf)
        -- inward only on one foot (the kicking foot carries nothing)
        if Body.sensor.foot_force[side == 'left' and 0 or 1] < 2 then f.cp_in = math.max(f.cp_in, ci) end
      end
      prev_com = com
      if Body.get_time() - t0 > 0.1 and s ~= 'kick_left' and s ~= 'kick_right' then kicking = false end
    end
    local bs = math.sqrt(r.ball.vx ^ 2 + r.ball.vy ^ 2)
    if bs > 0.05 and not t_contact then t_contact = Body.get_time() end
    if t_contact and Body.get_time() - t_contact < 0.1 and bs > f.launch then f.launch = bs end
    if t_contact and not f.later and Body.get_time() - t_contact >= 0.3 then f.later = bs end
    if not kicking and Body.get_time() - t0 > 3 and bs < 0.005 then break end
  end
  wait(0.5)
  local r1 = Sim.truth()
  f.d = math.sqrt((r1.ball.x - b0.x) ^ 2 + (r1.ball.y - b0.y) ^ 2)
  f.dir = wrap(math.atan2(r1.ball.y - b0.y, r1.ball.x - b0.x) - r0.yaw)
  f.falls = motion.falls[0] - falls0
  f.bad = f.falls > 0 or r1.fallen or Motion.state() ~= 'stance'
  print(string.format('# %-5s gap %.3f lat %+.3f: ball %.2f m (dir %+.2f rad), %.2f m/s off the foot, %.2f 0.3 s ' ..
    'later; tilt max %.2f rad, capture point %+.3f..%+.3f m, inward %+.3f m, yaw max %.3f, end %+.3f rad, ' ..
    'falls %d, %s%s', side, gap, lat, f.d, f.dir, f.launch, f.later or 0, f.tilt, f.cp_min, f.cp_max, f.cp_in,
    f.yaw, wrap(r1.yaw - r0.yaw), f.falls, Motion.state(), f.bad and ' FAIL' or ''))
  io.stdout:flush()
  return f
end

local worst, fallen, n = math.huge, 0, 0
for _, side in ipairs(sides) do
  for _, gap in ipairs(gaps) do
    for _, lat in ipairs(lats) do
      local f = kick(side, gap, lat)
      n = n + 1
      if f.bad then fallen = fallen + 1 end
      worst = math.min(worst, f.d)
    end
  end
end
print(string.format('sweep n=%d min=%.3f fallen=%d', n, worst, fallen))
