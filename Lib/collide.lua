-- Self-collision of a body (Modules/collide, libhrpcollide.so: coal through Pinocchio's geometry
-- model) through LuaJIT FFI, on the collision boxes of the URDF that robot.lua's `description` names,
-- joint angles in robot.lua's order.
--
--   local collide = require('collide')
--   local c = collide.load({ robot = 'hubo2plus' })   -- default ROBOT
--   c:margin(0.005)        -- m: shapes closer than this collide
--   c:ignore_near(3)       -- pairs of links up to 3 joints apart (a hip's, a shoulder's): dropped
--   c:ignore_at(q_ref)     -- pairs touching at a reference pose are the shapes' approximation: dropped
--   local n, a, b = c:check(q)   -- pairs in collision at q; the first pair's link names
--
-- Pairs of links one joint apart are never checked (Modules/collide/collide.h). Errors (a bad URDF,
-- a NaN angle) raise a Lua error naming the thing.
local ffi = require('ffi')
local native = require('native')

native.cdef('collide')   -- Modules/collide/collide.h

local C = native.load('collide')

local M = {}
local Checker = {}
Checker.__index = Checker

local b_err = ffi.new('char[512]')
local b_out = ffi.new('collide*[1]')
local b_first = ffi.new('int[1]')

function M.new(robot, urdf, files)
  local n = #robot.joints
  local names = ffi.new('const char*[?]', n)
  for i, j in ipairs(robot.joints) do names[i - 1] = j end
  if C.collide_new(urdf, n, names, b_out, b_err, 512) < 0 then
    return nil, string.format('%s: %s', files or urdf, ffi.string(b_err))
  end
  return setmetatable({ cc = ffi.gc(b_out[0], C.collide_free), n = n, q = ffi.new('double[?]', n),
    name = robot.name }, Checker)
end

function M.load(opts)
  return require('Config').from_description(M.new, opts and opts.robot and { robot = opts.robot } or nil)
end

local function check(self, rc)
  if rc < 0 then error(string.format('collide (%s): %s', self.name, ffi.string(C.collide_error(self.cc))), 3) end
  return rc
end

local function put(self, q)
  for i = 1, self.n do self.q[i - 1] = q[i] or 0 end
end

function Checker:ignore_at(q)
  put(self, q)
  return check(self, C.collide_ignore_at(self.cc, self.q))
end

function Checker:ignore_near(joints) return check(self, C.collide_ignore_near(self.cc, joints)) end
function Checker:margin(m) check(self, C.collide_set_margin(self.cc, m)) end
function Checker:npair() return C.collide_npair(self.cc) end
function Checker:check_us() return C.collide_check_us(self.cc) end

function Checker:check(q)
  put(self, q)
  local n = check(self, C.collide_check(self.cc, self.q, b_first))
  if n == 0 then return 0 end
  local k = b_first[0]
  return n, ffi.string(C.collide_pair_link(self.cc, k, 0)), ffi.string(C.collide_pair_link(self.cc, k, 1))
end

return M
