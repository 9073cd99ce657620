-- Kick scenario helpers shared by Tests/motion/sim_scenarios.lua (the pass/fail kick) and
-- Tests/motion/kick_trace.lua (the per-tick log): ball placement from the foot's forward
-- kinematics and the kicking foot's toe point in the world from the sim's truth.
local Body = require('Body')
local kin = require('kinematics')

local M = {}

-- the sole plate (shared/robots/op3_reference.txt, ank_roll_link sole_box): front edge ahead of the
-- ankle, centre outward of it, plate 8 mm thick
M.TOE, M.SOLE_Y, M.PLATE = 0.0635, 0.0125, 0.008

local model
local function get_model()
  model = model or kin.load()
  return model
end

local LEG = { 'hip_yaw', 'hip_roll', 'hip_pitch', 'knee', 'ank_pitch', 'ank_roll' }

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

-- Places the ball (centre at its radius) `gap` m ahead of the kicking foot's toe, in line with the
-- sole's centre, from the measured leg angles (torso tilt ignored). r = Sim.truth().
function M.place_ball(Sim, side, gap, r)
  local sgn = side == 'left' and 1 or -1
  local foot = get_model():leg_fk(side, M.leg(side))
  local bx, by = foot[1] + M.TOE + gap, foot[2] + sgn * M.SOLE_Y
  local c, s = math.cos(r.yaw), math.sin(r.yaw)
  Sim.teleport_ball(r.x + c * bx - s * by, r.y + s * bx + c * by)
end

return M
