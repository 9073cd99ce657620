-- Kick scenario helpers shared by Tests/motion/sim_scenarios.lua (the pass/fail kick) and the kick
-- tools (Tools/tune: kick_trace, kick_measure, kick_sweep, kick_tune): ball placement from the foot's forward
-- kinematics, the kicking foot's toe point in the world from the sim's truth, and waiting for the
-- motion process (which every scenario needs first), the start of a kick from stance or out of the walk,
-- and a push of the walking robot.
local Body = require('Body')
local kin = require('kinematics')
local shm = require('shm')

local M = {}

-- The left sole plate of the body (ROBOT) from its description: the URDF collision box named
-- sole* on the link the left leg's last joint moves, the front-most if there are several, against
-- the l_sole frame. TOE: its front face ahead of the foot frame (the sole point below the ankle);
-- SOLE_Y: its centre outward of it; PLATE: its thickness.
local function sole_plate()
  local Config = require('Config')
  local robot = Config.load('robot')
  local f = assert(io.open(Config.robot_file(robot.description), 'r'))
  local urdf = f:read('*a')
  f:close()
  local function nums(str) local t = {} for x in str:gmatch('[-%d.eE+]+') do t[#t + 1] = tonumber(x) end return t end
  local function child_of(joint)
    local body = urdf:match('<joint name="' .. joint .. '".-</joint>')
    return body and body:match('<child link="([^"]+)"')
  end
  local leg = robot.groups.lleg
  local link = assert(child_of(leg[#leg]), 'kick_setup: no link for ' .. leg[#leg])
  local sole = assert(urdf:match('<joint name="[^"]*" type="fixed">%s*<parent link="' .. link ..
    '"/>%s*<child link="l_sole"/>%s*<origin xyz="([^"]+)"'), 'kick_setup: no l_sole frame on ' .. link)
  sole = nums(sole)
  local body = assert(urdf:match('<link name="' .. link .. '">(.-)</link>'))
  local best
  for origin, size in body:gmatch('<collision name="sole[^"]*">%s*<origin xyz="([^"]+)"[^>]*>%s*' ..
      '<geometry><box size="([^"]+)"/></geometry>') do
    local o, sz = nums(origin), nums(size)
    local front = o[1] + sz[1] / 2
    if not best or front > best.front then best = { front = front, y = o[2], z = sz[3] } end
  end
  assert(best, 'kick_setup: no sole* collision box on ' .. link)
  return best.front - sole[1], best.y - sole[2], best.z
end
M.TOE, M.SOLE_Y, M.PLATE = sole_plate()

local model
local function get_model()
  model = model or kin.load()
  return model
end

local LEG = { 'hip_yaw', 'hip_roll', 'hip_pitch', 'knee', 'ank_pitch', 'ank_roll' }

-- Waits (robot time, up to 30 s) until the motion process runs: its tick follows the DCM's.
-- Returns the `motion` shm block, or nil when the motion process is not running.
function M.wait_for_motion(wait)
  local motion = shm.open('motion')
  for _ = 1, 300 do
    if motion.tick[0] ~= 0 and Body.get_tick() - motion.tick[0] <= 2 then return motion end
    wait(0.1)
  end
  return nil
end

-- wait_for_motion for a scenario that prints TAP lines: the motion block, or a failed TAP line
-- (through tap) and exit 1.
function M.need_motion(wait, tap)
  local motion = M.wait_for_motion(wait)
  if not motion then
    tap(false, 'the motion process is not running')
    os.exit(1)
  end
  return motion
end

-- Applies WALK_PARAMS='key=v[,v..];key=v' (Walk.set, retried until the walk takes it), so a
-- scenario runs with other walk parameters (e.g. feedback off); `note` (optional) logs each one.
function M.apply_walk_params(Walk, wait, note)
  for kv in (os.getenv('WALK_PARAMS') or ''):gmatch('[^;]+') do
    local key, v = kv:match('^(.-)=(.*)$')
    local vals = {}
    for x in v:gmatch('[^,]+') do vals[#vals + 1] = tonumber(x) end
    while not Walk.set(key, #vals == 1 and vals[1] or vals) do wait(0.01) end
    if note then note('walk parameter %s = %s', key, v) end
  end
end

-- leg joint angles (or velocities with get = Body.get_velocity) of one side
function M.leg(side, get)
  get = get or Body.get_position
  local pre = side == 'left' and 'l_' or 'r_'
  local q6 = {}
  for k, j in ipairs(LEG) do q6[k] = get(pre .. j) end
  return q6
end

-- R = Rz(yaw) Ry(pitch) Rx(roll) applied to v
local function rot(roll, pitch, yaw, v)
  local cr, sr, cp, sp, cy, sy = math.cos(roll), math.sin(roll), math.cos(pitch), math.sin(pitch),
    math.cos(yaw), math.sin(yaw)
  local x, y, z = v[1], v[2], v[3]
  y, z = cr * y - sr * z, sr * y + cr * z
  x, z = cp * x + sp * z, -sp * x + cp * z
  x, y = cy * x - sy * y, sy * x + cy * y
  return { x, y, z }
end
M.rot = rot

-- the middle of the sole plate's front edge, torso frame, from 6 leg angles
function M.toe_in_torso(side, q6)
  local f = get_model():leg_fk(side, q6)
  local sgn = side == 'left' and 1 or -1
  local o = rot(f[4], f[5], f[6], { M.TOE, sgn * M.SOLE_Y, M.PLATE / 2 })
  return { f[1] + o[1], f[2] + o[2], f[3] + o[3] }
end

-- the kicking foot's pitch in the torso frame (toe down positive), from 6 leg angles
function M.foot_pitch(side, q6)
  return get_model():leg_fk(side, q6)[5]
end

-- the toe's velocity relative to the torso (torso frame) from the joint velocities: J(q) qd by
-- central differences of the forward kinematics
function M.toe_velocity_in_torso(side, q6, qd6)
  local h = 1e-5
  local a, b = {}, {}
  for k = 1, 6 do a[k], b[k] = q6[k] + h * qd6[k], q6[k] - h * qd6[k] end
  local pa, pb = M.toe_in_torso(side, a), M.toe_in_torso(side, b)
  return { (pa[1] - pb[1]) / (2 * h), (pa[2] - pb[2]) / (2 * h), (pa[3] - pb[3]) / (2 * h) }
end

-- The whole-body COM relative to the support foot's ankle (the foot not kicking), in the torso's
-- heading frame: { forward, inward (towards the kicking foot), up }, from the measured joint
-- angles, the mass model and the torso's truth. side: the kicking side. r = Sim.truth().
function M.com_over_support(side, r)
  local m = get_model()
  local cm = m:com(Body.get_positions())
  local sa = m:leg_fk(side == 'left' and 'right' or 'left', M.leg(side == 'left' and 'right' or 'left'))
  local d = rot(r.roll, r.pitch, 0, { cm[1] - sa[1], cm[2] - sa[2], cm[3] - sa[3] })
  return { d[1], (side == 'left' and 1 or -1) * d[2], d[3] }
end

-- The toe's velocity in the world: the joints' (FK) plus the torso's turning (gyro) and moving
-- (truth r against the truth `prev` dt s before; nil: left out). Returns it and the toe (torso frame).
function M.toe_velocity(side, r, prev, dt)
  local q6, qd6 = M.leg(side), M.leg(side, Body.get_velocity)
  local toe = M.toe_in_torso(side, q6)
  local rv = M.toe_velocity_in_torso(side, q6, qd6)
  local g = Body.get_gyro()
  local v = rot(r.roll, r.pitch, r.yaw, { rv[1] + g[2] * toe[3] - g[3] * toe[2],
    rv[2] + g[3] * toe[1] - g[1] * toe[3], rv[3] + g[1] * toe[2] - g[2] * toe[1] })
  if prev then
    v[1], v[2], v[3] = v[1] + (r.x - prev.x) / dt, v[2] + (r.y - prev.y) / dt, v[3] + (r.z - prev.z) / dt
  end
  return v, toe
end

-- The torso frame from the sim's truth r (the torso's pose): a point in the torso frame to the
-- world, and back.
function M.to_world(r, v)
  local w = rot(r.roll, r.pitch, r.yaw, v)
  return { r.x + w[1], r.y + w[2], r.z + w[3] }
end
function M.to_torso(r, p)
  local c, s = math.cos(r.yaw), math.sin(r.yaw)
  local dx, dy, dz = p[1] - r.x, p[2] - r.y, p[3] - r.z
  local x, y, z = c * dx + s * dy, -s * dx + c * dy, dz
  -- R = Rz Ry Rx: undo the pitch, then the roll
  local cp, sp = math.cos(r.pitch), math.sin(r.pitch)
  x, z = cp * x - sp * z, sp * x + cp * z
  local cr, sr = math.cos(r.roll), math.sin(r.roll)
  return { x, cr * y + sr * z, -sr * y + cr * z }
end

-- The ball's centre in the kicking foot's frame, from the middle of its sole plate (x forward,
-- y outward, z up; the plate's front face is at x = TOE, its top at z = PLATE / 2). q: all joint
-- angles; r = Sim.truth() (the torso's pose and the ball). Tells which part of the foot meets it.
function M.ball_in_foot(side, q, r)
  local m = get_model()
  local sgn = side == 'left' and 1 or -1
  -- link frames: axes of the zero pose carried along; the sole point at the zero pose is the
  -- reference for the foot's own frame
  local P = m:link_poses(q)[Body.index((side == 'left' and 'l_' or 'r_') .. 'ank_roll')]
  local f0 = m:leg_fk(side, { 0, 0, 0, 0, 0, 0 })
  local b = M.to_torso(r, { r.ball.x, r.ball.y, r.ball.z })
  local R, v = P.R, { b[1] - P[1], b[2] - P[2], b[3] - P[3] }
  local l = { R[1] * v[1] + R[4] * v[2] + R[7] * v[3], R[2] * v[1] + R[5] * v[2] + R[8] * v[3],
    R[3] * v[1] + R[6] * v[2] + R[9] * v[3] }
  return { l[1] - f0[1], sgn * (l[2] - f0[2]) - M.SOLE_Y, l[3] - f0[3] - M.PLATE / 2 }
end

-- Places the ball (centre at its radius) `gap` m ahead of the kicking foot's toe, in line with the
-- sole's centre (or `lateral` m outward of it), from the measured leg angles and the torso's
-- pose (its tilt included). r = Sim.truth().
function M.place_ball(Sim, side, gap, r, lateral)
  local sgn = side == 'left' and 1 or -1
  local sole = M.to_world(r, get_model():leg_fk(side, M.leg(side)))
  local bx, by = M.TOE + gap, sgn * (M.SOLE_Y + (lateral or 0))
  local c, s = math.cos(r.yaw), math.sin(r.yaw)
  Sim.teleport_ball(sole[1] + c * bx - s * by, sole[2] + s * bx + c * by)
end

-- Waits (up to 20 s of robot time) until the motion process is in stance: after a fall the robot
-- stands up first.
function M.until_stance(Motion, wait)
  for _ = 1, 400 do
    if Motion.state() == 'stance' then break end
    wait(0.05)
  end
end

-- A fresh world for a walking kick: the robot standing at (-3.5, 0) facing along the field, then
-- walking at vx m/s for 2.5 s (the ball out of the way). The walk-kick scenarios share it
-- (walk_kick_scenario.lua, Tools/tune/walk_kick_tune.lua).
function M.walk_steady(Sim, Motion, Walk, wait, vx)
  Sim.reset()
  wait(0.2)
  Motion.request('stand')
  M.until_stance(Motion, wait)
  Sim.teleport_robot(-3.5, 0, 0)
  Sim.teleport_ball(4.0, -3.5)
  wait(1.0)
  Motion.request('walk')
  Walk.set_velocity(vx, 0, 0)
  wait(2.5)
end

-- A fresh world for a kick: the robot at a field corner facing along the diagonal (10 m of free
-- carpet), standing; the ball placed as place_ball does. Returns the truth after the ball settled.
function M.setup(Sim, Motion, wait, side, gap, lateral)
  Sim.reset()
  wait(0.2)
  Sim.teleport_robot(-4.3, -3.3, math.atan2(6.6, 8.6))
  Sim.teleport_ball(4.0, -3.5)
  wait(0.2)
  Motion.request('stand')
  M.until_stance(Motion, wait)
  wait(2.0)
  M.place_ball(Sim, side, gap, Sim.truth(), lateral)
  wait(0.5)
  return Sim.truth()
end

-- Pushes the walking robot at its torso for 0.1 s with f N, 'forward' or sideways (to its left),
-- and watches 3 s of robot time: true when it fell (the sim's truth, or the motion process's count).
-- The push scenarios share it (sim_scenarios.lua's push search, balance_scenarios.lua's, push_sweep.lua).
function M.push_falls(Sim, Motion, wait_until, dir, f)
  local a = Sim.truth()
  local falls0 = Motion.falls()
  if dir == 'forward' then
    Sim.push(f * math.cos(a.yaw), f * math.sin(a.yaw), 0.1)
  else
    Sim.push(-f * math.sin(a.yaw), f * math.cos(a.yaw), 0.1)
  end
  return wait_until(function() return Sim.truth().fallen or Motion.falls() > falls0 end, 3)
end

-- A fresh world with the robot in the field's far corner facing its centre (the ball at ball = { x, y }
-- too, or left where the reset puts it), in a settled stance: after a fall the motion process stands up
-- first, so a push never starts on a robot still lying down. who: the caller's name for the error.
function M.fresh_stance(Sim, Motion, Walk, wait, wait_until, who, ball)
  Sim.reset()
  wait(0.2)
  Sim.teleport_robot(-4.3, -3.3, math.atan2(6.6, 8.6))
  if ball then Sim.teleport_ball(ball[1], ball[2]) end
  wait(0.2)
  Walk.set_velocity(0, 0, 0)
  Motion.request('stand')
  if not wait_until(function() return Motion.state() == 'stance' end, 15) then
    error(who .. ': the robot is not back in stance 15 s after a reset (state ' .. Motion.state() .. ')')
  end
  wait(1.5)
end

return M
