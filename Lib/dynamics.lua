-- The rigid-body model of a body with a floating base, through LuaJIT FFI over Modules/dynamics
-- (libhrpdyn.so, Pinocchio): frame poses and Jacobians, the centre of mass and its Jacobian, the
-- mass matrix, gravity torques, nonlinear effects and inverse dynamics. Built from the URDF that
-- robot.lua's `description` names, in robot.lua's joint order (`joints`, the shm order).
--
--   local dynamics = require('dynamics')
--   local m = dynamics.load()                     -- ROBOT's body; dynamics.load({ robot = 'hubo2plus' })
--   m:set(q [, base [, v]])                       -- the state every query below is of
--   local p = m:pose('r_palm')                    -- { x, y, z, R = {9} } world pose of a link or joint frame
--   local J = m:jacobian('r_palm' [, 'local'])    -- 6 rows of nv: J[r][c]
--   local c, Jc = m:com(), m:com_jacobian()       -- { x, y, z }; 3 rows of nv
--   local M = m:mass_matrix()                     -- nv rows of nv (CRBA)
--   local g, h = m:gravity(), m:nonlinear()       -- nv each: g(q), C(q, v) v + g(q)
--   local tau = m:inverse_dynamics(a)             -- nv: M a + h (RNEA)
--   m.n, m.nv, m.joints, m.mass, m.name           -- joints, 6 + joints, names in order, kg, body
--
-- State: q is a 1-based table of joint angles (rad) in robot order (a missing entry is 0). base is
-- the pose of the URDF's root link in the world: nil (at the origin, upright), { x, y, z, roll,
-- pitch, yaw } (R = Rz(yaw) Ry(pitch) Rx(roll)) or { x, y, z, qx, qy, qz, qw }. v (nil: at rest)
-- has nv entries: the base's twist (vx vy vz wx wy wz, in the root link's frame), then the joint
-- rates in robot order. Jacobian columns, mass-matrix rows and columns and the torque vectors
-- (gravity, nonlinear, inverse_dynamics, an acceleration a) are in that same order: column 6 + i is
-- robot joint i. World: z up, gravity -9.81 m/s^2 along z; metres, radians, kg, N, N m.
-- Jacobians map velocities to the frame's linear velocity (rows 1-3, of its origin) and angular
-- velocity (rows 4-6) in world-aligned axes (Pinocchio's LOCAL_WORLD_ALIGNED: what task-space
-- control needs), or with 'local' in the frame's own axes. Pose rotations are row-major 3x3
-- (columns = the frame's axes in the world).
-- Errors (an unknown frame or joint, a NaN or infinite input, a bad URDF) raise a Lua error naming
-- the thing; a refused state leaves the previous one. Pass `out` tables to reuse them: the C buffers
-- are allocated once per model.
local ffi = require('ffi')
local native = require('native')

local type, error, tostring, format = type, error, tostring, string.format
local sin, cos = math.sin, math.cos

native.cdef('dynamics')   -- Modules/dynamics/dynamics.h

local C = native.load('dyn')

local M = {}

local b_model = ffi.new('dyn_model*[1]')
local b_err = ffi.new('char[512]')

local Model = {}
Model.__index = Model

local function fail(m, what)
  error(format('dynamics: %s: %s', m.name, what), 3)
end

local function check(m, rc)
  if rc < 0 then fail(m, ffi.string(C.dyn_error(m.cm))) end
  return rc
end

-- Builds a model from a robot config (its joints) and the path of its URDF; config names it in
-- messages. Returns the model, or nil and a message naming the file and the joint.
function M.new(robot, urdf, config)
  if type(robot) ~= 'table' or type(rawget(robot, 'joints')) ~= 'table' then
    error('dynamics.new: robot config with a joints list expected', 2)
  end
  if type(urdf) ~= 'string' then error('dynamics.new: path of the URDF expected', 2) end
  local names = robot.joints
  local n = #names
  local cjoints = ffi.new('const char*[?]', math.max(n, 1))
  for i = 1, n do cjoints[i - 1] = names[i] end
  local rc = C.dyn_model_load(urdf, n, cjoints, b_model, b_err, 512)
  if rc ~= 0 then return nil, format('dynamics: %s: %s', config or urdf, ffi.string(b_err)) end
  local nv = n + 6
  local joints = {}
  for i = 1, n do joints[i] = names[i] end
  return setmetatable({
    cm = ffi.gc(b_model[0], C.dyn_model_destroy),
    name = rawget(robot, 'name') or config or urdf,
    file = urdf,
    n = n,
    nv = nv,
    joints = joints,
    mass = C.dyn_total_mass(b_model[0]),
    frame_ids = {},   -- name -> frame id, filled as frames are asked for
    b_q = ffi.new('double[?]', math.max(n, 1)),
    b_base = ffi.new('double[7]'),
    b_v = ffi.new('double[?]', nv),
    b_vec = ffi.new('double[?]', nv),
    b_mat = ffi.new('double[?]', nv * nv),
    b_pos = ffi.new('double[3]'),
    b_rot = ffi.new('double[9]'),
  }, Model)
end

-- The model of a body (opts: nil = ROBOT, or { robot = name }): its robot.lua and description.
function M.load(opts) return require('Config').from_description(M.new, opts) end

-- The base pose as Pinocchio's 7 numbers (position, quaternion x y z w).
local function fill_base(m, base)
  local b = m.b_base
  if #base == 6 then
    local hr, hp, hy = base[4] / 2, base[5] / 2, base[6] / 2
    local cr, sr, cp, sp, cy, sy = cos(hr), sin(hr), cos(hp), sin(hp), cos(hy), sin(hy)
    b[3] = sr * cp * cy - cr * sp * sy
    b[4] = cr * sp * cy + sr * cp * sy
    b[5] = cr * cp * sy - sr * sp * cy
    b[6] = cr * cp * cy + sr * sp * sy
  elseif #base == 7 then
    for k = 3, 6 do b[k] = base[k + 1] end
  else
    fail(m, format('base: 6 (x y z roll pitch yaw) or 7 (x y z qx qy qz qw) numbers expected, got %d', #base))
  end
  for k = 0, 2 do b[k] = base[k + 1] end
  return b
end

-- Sets the state all queries are of: joint angles q (robot order), base pose, velocities v.
function Model:set(q, base, v)
  if type(q) ~= 'table' then fail(self, 'joint angles must be a table') end
  for i = 1, self.n do self.b_q[i - 1] = q[i] or 0 end
  local cb, cv = nil, nil
  if base ~= nil then
    if type(base) ~= 'table' then fail(self, 'base must be a table') end
    cb = fill_base(self, base)
  end
  if v ~= nil then
    if type(v) ~= 'table' then fail(self, 'velocities must be a table') end
    for c = 1, self.nv do self.b_v[c - 1] = v[c] or 0 end
    cv = self.b_v
  end
  check(self, C.dyn_set_state(self.cm, cb, self.b_q, cv))
end

-- The id of a frame (a link, else a joint), cached.
function Model:frame_id(name)
  local id = self.frame_ids[name]
  if id then return id end
  if type(name) ~= 'string' then fail(self, 'frame name expected, got ' .. tostring(name)) end
  id = check(self, C.dyn_frame_id(self.cm, name))
  self.frame_ids[name] = id
  return id
end

-- rows x cols of the C matrix buffer into a table of rows.
local function rows(buf, nr, nc, out)
  out = out or {}
  for r = 1, nr do
    local row = out[r] or {}
    local o = (r - 1) * nc
    for c = 1, nc do row[c] = buf[o + c - 1] end
    out[r] = row
  end
  return out
end

local function vector(buf, n, out)
  out = out or {}
  for c = 1, n do out[c] = buf[c - 1] end
  return out
end

-- World pose of a frame: { x, y, z, R = {9} }.
function Model:pose(name, out)
  check(self, C.dyn_frame_pose(self.cm, self:frame_id(name), self.b_pos, self.b_rot))
  out = out or {}
  out[1], out[2], out[3] = self.b_pos[0], self.b_pos[1], self.b_pos[2]
  out.R = vector(self.b_rot, 9, out.R)
  return out
end

local REF = { world = 0, ['local'] = 1 }

-- A frame's 6 x nv Jacobian; ref 'world' (default: world-aligned axes) or 'local'.
function Model:jacobian(name, ref, out)
  local r = REF[ref or 'world']
  if not r then fail(self, format("reference frame '%s': 'world' or 'local'", tostring(ref))) end
  check(self, C.dyn_frame_jacobian(self.cm, self:frame_id(name), r, self.b_mat))
  return rows(self.b_mat, 6, self.nv, out)
end

-- Whole-body centre of mass { x, y, z } (world).
function Model:com(out)
  check(self, C.dyn_com(self.cm, self.b_pos, nil))
  return vector(self.b_pos, 3, out)
end

-- The COM's 3 x nv Jacobian (world axes).
function Model:com_jacobian(out)
  check(self, C.dyn_com(self.cm, self.b_pos, self.b_mat))
  return rows(self.b_mat, 3, self.nv, out)
end

-- The nv x nv mass matrix (CRBA).
function Model:mass_matrix(out)
  check(self, C.dyn_mass_matrix(self.cm, self.b_mat))
  return rows(self.b_mat, self.nv, self.nv, out)
end

-- Gravity torques g(q) (nv).
function Model:gravity(out)
  check(self, C.dyn_gravity(self.cm, self.b_vec))
  return vector(self.b_vec, self.nv, out)
end

-- Nonlinear effects C(q, v) v + g(q) (nv).
function Model:nonlinear(out)
  check(self, C.dyn_nonlinear(self.cm, self.b_vec))
  return vector(self.b_vec, self.nv, out)
end

-- Generalized forces for an acceleration a (nv): M a + C v + g (RNEA).
function Model:inverse_dynamics(a, out)
  if type(a) ~= 'table' then fail(self, 'acceleration must be a table') end
  for c = 1, self.nv do self.b_v[c - 1] = a[c] or 0 end
  check(self, C.dyn_inverse_dynamics(self.cm, self.b_v, self.b_vec))
  return vector(self.b_vec, self.nv, out)
end

return M
