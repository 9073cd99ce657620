-- One measured kick in the sim (lockstep), shared by Tools/tune/kick_sweep.lua and kick_tune.lua:
-- the ball's distance and direction (from the robot's heading), its speed after contact and 0.3 s
-- later (rolling), the torso's largest tilt from upright, the capture point (COM + its velocity /
-- sqrt(g / height)) against the support foot's ankle while the kick runs (forward range; inward on
-- one foot), the torso's yaw, falls counted by the motion process and the state at the end.
local shm = require('shm')
local ks = require('kick_setup')

local M = {}
local motion

local function wrap(a) return (a + math.pi) % (2 * math.pi) - math.pi end
local DT = 0.008

-- One kick from a fresh world (kick_setup.setup) with the ball `gap` m ahead of the toe and `lat` m
-- outward; returns its figures (see the header). env = { Sim, Motion, wait, Body } (the REPL's).
function M.kick(env, side, gap, lat)
  local Sim, Motion, wait, Body = env.Sim, env.Motion, env.wait, env.Body
  motion = motion or shm.open('motion')
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
  f.state, f.yaw_end = Motion.state(), wrap(r1.yaw - r0.yaw)
  f.bad = f.falls > 0 or r1.fallen or f.state ~= 'stance'
  return f
end

-- Sets walk parameters in the running motion process (Walk.set; one per tick): params =
-- { ['kick.leg.4.hip'] = -1.7, ... } as kick_tune.lua writes them. The swing phase's targets
-- (kick.leg.4.*) are held by the follow-through (kick.leg.5.*): set there too.
local HELD = { x = true, z = true, hip = true, knee = true, ankle = true, arm = true }
function M.apply(params, wait)
  local Walk = require('Walk')
  local function set(path, v)
    for _ = 1, 100 do
      if Walk.set(path, v) then return end
      wait(0.01)
    end
    error('kick_measure: the motion process did not take ' .. path)
  end
  for path, v in pairs(params) do
    set(path, v)
    local key = path:match('^kick%.leg%.4%.(%w+)$')
    if key and HELD[key] then set('kick.leg.5.' .. key, v) end
  end
  wait(0.05)
end

-- Parameters from the file named by the environment's KICK_PARAMS (a Lua file returning a table as
-- for M.apply), applied; nothing when it is not set.
function M.apply_env(wait)
  local file = os.getenv('KICK_PARAMS')
  if file and file ~= '' then M.apply(assert(dofile(file)), wait) end
end

-- One line of figures for a kick measured by M.kick.
function M.describe(side, gap, lat, f)
  return string.format('%-5s gap %.3f lat %+.3f: ball %.2f m (dir %+.2f rad), %.2f m/s off the foot, %.2f 0.3 s ' ..
    'later; tilt max %.2f rad, capture point %+.3f..%+.3f m, inward %+.3f m, yaw max %.3f, end %+.3f rad, ' ..
    'falls %d, %s%s', side, gap, lat, f.d, f.dir, f.launch, f.later or 0, f.tilt, f.cp_min, f.cp_max, f.cp_in,
    f.yaw, f.yaw_end, f.falls, f.state, f.bad and ' FAIL' or '')
end

return M
