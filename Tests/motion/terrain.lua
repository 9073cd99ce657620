-- Terrain layouts for the walking tests (the sim world's `objects`, Config/platforms/Sim/sim.lua):
-- each a list of static boxes and the robot's start pose in front of them, facing +x. Used by
-- Tests/motion/terrain_test.sh (writes a site overlay with them) and terrain_scenario.lua (the
-- start pose, and where the robot must get to).
--   luajit Tests/motion/terrain.lua sim LAYOUT   -- prints the site's sim.lua for LAYOUT
local rad = math.pi / 180
local M = {}

-- the robot starts at (x0, y0) facing +x, on free carpet clear of the centre circle and the goals
local x0, y0 = -3.0, 2.0

-- no object: the same walk on the flat carpet (a reference for the others)
M.flat = { start = { x0, y0, 0 }, finish = x0 + 1.4, objects = {} }

-- a 1 cm board 0.8 m long, 0.4 m ahead: a step up, then a step down
M.step = {
  start = { x0, y0, 0 },
  finish = x0 + 1.4,       -- m along x: past the board's far edge by 0.2 m
  objects = { { pos = { x0 + 0.8, y0, 0.005 }, size = { 0.8, 1.0, 0.01 }, rpy = { 0, 0, 0 } } },
}

-- a 5 degree ramp up (0.6 m), a platform (0.4 m) at its height, a 5 degree ramp down (0.6 m): the
-- ramps are tilted boards whose top faces meet the carpet and the platform's top at their edges
local function ramp_layout()
  local a, len, t = 5 * rad, 0.6, 0.05
  local rise = len * math.sin(a)
  local run = len * math.cos(a)
  local xa = x0 + 0.4                          -- foot of the ramp up
  local xb = xa + run                          -- the platform
  local xc = xb + 0.4                          -- top of the ramp down
  -- a board whose top face runs from (xs, 0) up/down: centre = top face's centre - t/2 * normal
  local function board(xs, up)
    local pitch = up and -a or a
    local zc = rise / 2
    local nx, nz = math.sin(pitch), math.cos(pitch)
    return { pos = { xs + run / 2 - nx * t / 2, y0, zc - nz * t / 2 }, size = { len, 1.0, t }, rpy = { 0, pitch, 0 } }
  end
  return {
    start = { x0, y0, 0 },
    finish = xc + run + 0.2,
    objects = {
      board(xa, true),
      { pos = { xb + 0.2, y0, rise / 2 }, size = { 0.4, 1.0, rise }, rpy = { 0, 0, 0 } },
      board(xc, false),
    },
  }
end
M.ramp = ramp_layout()

-- the site overlay's sim.lua for a layout
function M.sim_lua(name)
  local l = M[name]
  if type(l) ~= 'table' then error("terrain: unknown layout '" .. tostring(name) .. "' (flat, step, ramp)", 2) end
  local out = { '-- Tests/motion/terrain.lua ' .. name, 'return {', '  objects = {' }
  local function v3(v) return string.format('{ %.6f, %.6f, %.6f }', v[1], v[2], v[3]) end
  for _, o in ipairs(l.objects) do
    out[#out + 1] = string.format('    { pos = %s, size = %s, rpy = %s },', v3(o.pos), v3(o.size), v3(o.rpy))
  end
  out[#out + 1] = '  },'
  out[#out + 1] = '}'
  return table.concat(out, '\n') .. '\n'
end

if arg and arg[0] and arg[0]:match('terrain%.lua$') and arg[1] == 'sim' then
  io.write(M.sim_lua(arg[2]))
end
return M
