-- What the whole-body scenarios (Tests/wbc/*.lua, run by ./run_repl in lockstep) share: starting the
-- wbc state from a settled stance, the stance frame as the sim's truth has it, points and distances.
--   local scene = require('wbc_scene')
--   scene.start(wait, tap)          -- stands 3 s, then Motion.request('wbc') (1 s): a TAP line
--   local f = scene.stance_frame()  -- f.to_field({x, y, z}), f.to_stance({x, y, z}): stance frame <-> field
--   scene.xyz(Sim.link_truth('r_palm')), scene.dist(a, b), scene.in_torso('r_palm')
--   scene.in_link('r_palm', 'torso')  -- a link's origin in another link's frame
package.path = os.getenv('HRP_ROOT') .. '/Tests/motion/?.lua;' .. package.path
local ks = require('kick_setup')
local Sim, Motion, WBC = require('Sim'), require('Motion'), require('WBC')

local M = {}

function M.xyz(p) return { p.x, p.y, p.z } end

-- Vector d (field axes) in the axes of truth pose t: R^T d, R = Rz(yaw) Ry(pitch) Rx(roll).
function M.to_local(t, d)
  local cr, sr, cp, sp, cy, sy = math.cos(t.roll), math.sin(t.roll), math.cos(t.pitch), math.sin(t.pitch),
    math.cos(t.yaw), math.sin(t.yaw)
  local R = { { cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr },
    { sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr }, { -sp, cp * sr, cp * cr } }
  local out = {}
  for c = 1, 3 do out[c] = R[1][c] * d[1] + R[2][c] * d[2] + R[3][c] * d[3] end
  return out
end

-- Where link `name` is in the root link's frame (Sim.truth's: the pelvis on the Hubo2+; the limb's
-- own doing and the waist's, whatever the legs do).
function M.in_torso(name)
  local p, t = Sim.link_truth(name), Sim.truth()
  return M.to_local(t, { p.x - t.x, p.y - t.y, p.z - t.z })
end
-- Where link `name` is in link `of`'s frame (Sim.link_truth of both: e.g. a hand against the link its
-- arm hangs from, whatever the waist and the legs do).
function M.in_link(name, of)
  local p, t = Sim.link_truth(name), Sim.link_truth(of)
  return M.to_local(t, { p.x - t.x, p.y - t.y, p.z - t.z })
end

function M.dist(a, b) return math.sqrt((a[1] - b[1]) ^ 2 + (a[2] - b[2]) ^ 2 + (a[3] - b[3]) ^ 2) end

-- The motion process up, a settled stance, then the wbc state running (checked: one TAP line).
function M.start(wait, tap)
  ks.need_motion(wait, tap)
  Motion.request('stand')
  wait(3)
  Motion.request('wbc')
  wait(1)
  tap(Motion.state() == 'wbc' and WBC.status().active, 'the wbc state runs (state ' .. Motion.state() .. ')')
end

-- The stance frame in the field now: midway between the soles, x along their mean heading.
function M.stance_frame()
  local l, r = Sim.link_truth('l_sole'), Sim.link_truth('r_sole')
  local ox, oy, oz = (l.x + r.x) / 2, (l.y + r.y) / 2, (l.z + r.z) / 2
  local yaw = (l.yaw + r.yaw) / 2
  local c, s = math.cos(yaw), math.sin(yaw)
  return {
    origin = { ox, oy, oz }, yaw = yaw,
    to_field = function(p) return { ox + c * p[1] - s * p[2], oy + s * p[1] + c * p[2], oz + p[3] } end,
    to_stance = function(p)
      local dx, dy = p[1] - ox, p[2] - oy
      return { c * dx + s * dy, -s * dx + c * dy, p[3] - oz }
    end,
  }
end

return M
