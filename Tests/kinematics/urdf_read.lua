-- A small URDF reader for tests, independent of the C++ parser (Modules/description): links (mass,
-- COM), joints (type, parent/child link, origin xyz/rpy, axis, limit, dynamics, the actuator
-- comment Tools/urdf/gen_urdf.py writes), and a forward kinematics over them (world = root link frame).
local sin, cos, sqrt = math.sin, math.cos, math.sqrt

local M = {}

local function nums(s)
  local t = {}
  for v in (s or ''):gmatch('[^%s]+') do t[#t + 1] = tonumber(v) end
  return t
end

local function attr(tag, name) return tag and tag:match(name .. '="([^"]*)"') end

-- Reads a URDF: { links = { name = { mass, com } }, joints = { name = {...} }, by_child = {} }.
function M.read(path)
  local f = assert(io.open(path, 'r'))
  local text = f:read('*a')
  f:close()
  local links, joints, by_child = {}, {}, {}
  for name in text:gmatch('<link%s+name="([^"]+)"') do links[name] = { massless = true } end
  for name, body in text:gmatch('<link%s+name="([^"]+)"%s*>(.-)</link>') do
    local inertial = body:match('<inertial>(.-)</inertial>')
    if inertial then
      links[name] = {
        mass = tonumber(attr(inertial:match('<mass[^>]*>'), 'value')),
        com = nums(attr(inertial:match('<origin[^>]*>'), 'xyz')),
      }
    end
  end
  for name, jtype, body in text:gmatch('<joint%s+name="([^"]+)"%s+type="([^"]+)"%s*>(.-)</joint>') do
    local origin, limit, dyn = body:match('<origin[^>]*>'), body:match('<limit[^>]*>'), body:match('<dynamics[^>]*>')
    local j = {
      type = jtype,
      parent = attr(body:match('<parent[^>]*>'), 'link'),
      child = attr(body:match('<child[^>]*>'), 'link'),
      xyz = nums(attr(origin, 'xyz')),
      rpy = nums(attr(origin, 'rpy')),
      axis = nums(attr(body:match('<axis[^>]*>'), 'xyz')),
      actuator = body:match('<!%-%- actuator (%S+) %-%->'),
    }
    if limit then
      j.lower, j.upper = tonumber(attr(limit, 'lower')), tonumber(attr(limit, 'upper'))
      j.effort, j.velocity = tonumber(attr(limit, 'effort')), tonumber(attr(limit, 'velocity'))
    end
    if dyn then j.damping, j.friction = tonumber(attr(dyn, 'damping')), tonumber(attr(dyn, 'friction')) end
    if #j.rpy == 0 then j.rpy = { 0, 0, 0 } end
    if #j.xyz == 0 then j.xyz = { 0, 0, 0 } end
    joints[name] = j
    by_child[j.child] = name
  end
  return { links = links, joints = joints, by_child = by_child }
end

local function matmul(A, B)
  local C = {}
  for i = 0, 2 do
    for j = 0, 2 do
      local v = 0
      for k = 0, 2 do v = v + A[3 * i + k + 1] * B[3 * k + j + 1] end
      C[3 * i + j + 1] = v
    end
  end
  return C
end
M.matmul = matmul

function M.rpy_rot(r, p, y)
  local Rx = { 1, 0, 0, 0, cos(r), -sin(r), 0, sin(r), cos(r) }
  local Ry = { cos(p), 0, sin(p), 0, 1, 0, -sin(p), 0, cos(p) }
  local Rz = { cos(y), -sin(y), 0, sin(y), cos(y), 0, 0, 0, 1 }
  return matmul(Rz, matmul(Ry, Rx))
end

function M.axis_rot(a, q)
  local n = sqrt(a[1] ^ 2 + a[2] ^ 2 + a[3] ^ 2)
  local x, y, z = a[1] / n, a[2] / n, a[3] / n
  local c, s, t = cos(q), sin(q), 1 - cos(q)
  return { t * x * x + c, t * x * y - s * z, t * x * z + s * y,
    t * x * y + s * z, t * y * y + c, t * y * z - s * x,
    t * x * z - s * y, t * y * z + s * x, t * z * z + c }
end

function M.apply(R, v)
  return { R[1] * v[1] + R[2] * v[2] + R[3] * v[3], R[4] * v[1] + R[5] * v[2] + R[6] * v[3],
    R[7] * v[1] + R[8] * v[2] + R[9] * v[3] }
end

-- Pose { R = {9}, p = {3} } of every link (and frame) in the root link's frame; angle(name) gives
-- a revolute joint's angle.
function M.fk(u, angle)
  local poses = {}
  local function pose(link)
    if poses[link] then return poses[link] end
    local jn = u.by_child[link]
    if not jn then
      poses[link] = { R = { 1, 0, 0, 0, 1, 0, 0, 0, 1 }, p = { 0, 0, 0 } }
      return poses[link]
    end
    local j = u.joints[jn]
    local P = pose(j.parent)
    local Rj = M.rpy_rot(j.rpy[1], j.rpy[2], j.rpy[3])
    if j.type == 'revolute' then Rj = matmul(Rj, M.axis_rot(j.axis, angle(jn))) end
    local o = M.apply(P.R, j.xyz)
    poses[link] = { R = matmul(P.R, Rj), p = { P.p[1] + o[1], P.p[2] + o[2], P.p[3] + o[3] } }
    return poses[link]
  end
  for name in pairs(u.links) do pose(name) end
  return poses
end

return M
