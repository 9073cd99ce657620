-- The kinematic whole-body controller (Modules/wbc, libhrpwbc.so) through LuaJIT FFI: tasks in strict
-- priority levels over a body's rigid-body model, the soles held as contacts, joint limits kept;
-- each step gives the joint angles to command. Built from the URDF that robot.lua's `description`
-- names, in robot.lua's joint order; limits from robot.lua's `limits` and the actuators' speeds.
--
--   local wbc = require('wbc')
--   local c = wbc.load({ dt = 0.005 })            -- ROBOT's body; { robot = 'hubo2plus', dt = ... }
--   c:contacts({ 'l_sole', 'r_sole' })
--   c:reset(q)                                     -- present joint angles (robot order, 1-based)
--   c:add('com', 'com_xy', { level = 1, gain = 5, max_rate = 0.1 })
--   c:add('r_palm', 'position', { frame = 'r_palm', level = 2, gain = 4, max_rate = 0.3 })
--   c:target('r_palm', { 0.35, -0.25, 0.90 })      -- stance frame, m; nil drops the target
--   local q = c:step(out)                          -- joint angles to command (robot order)
--   c:status('r_palm')  --> { kind, frame, level, enabled, feasible, error, sigma_min, sigma_max, rank, rows }
--   c:pose('r_palm')    --> { x, y, z, R = {9} } the model's, stance frame ('com': position only)
--
-- Kinds: position (3), orientation (9, row-major), pose (12: position then rotation), com (3),
-- com_xy (2), posture (one angle per joint). The stance frame: on the ground midway between the
-- contacts at reset, x along their mean heading, z up. Errors (unknown frame, kind or task, a NaN or
-- a target of the wrong size) raise a Lua error naming it; the controller is left as it was.
local ffi = require('ffi')
local native = require('native')

local type, error, tostring, format = type, error, tostring, string.format

native.cdef('wbc')   -- Modules/wbc/wbc.h

local C = native.load('wbc')

local M = {}

M.KINDS = { position = C.WBC_POSITION, orientation = C.WBC_ORIENTATION, pose = C.WBC_POSE, com = C.WBC_COM,
  com_xy = C.WBC_COM_XY, posture = C.WBC_POSTURE }
local KIND_NAME = {}
for name, k in pairs(M.KINDS) do KIND_NAME[tonumber(k)] = name end

local Ctl = {}
Ctl.__index = Ctl

local b_err = ffi.new('char[512]')
local b_ctl = ffi.new('wbc*[1]')
local b_status = ffi.new('wbc_task_status')

local function check(self, rc)
  if rc < 0 then error(format('wbc (%s): %s', self.name, ffi.string(C.wbc_error(self.cw))), 3) end
  return rc
end

-- A controller of a robot config's body (its joints), from the URDF at `urdf`, stepping by dt.
function M.new(robot, urdf, dt, files)
  local joints = robot.joints
  local n = #joints
  local names = ffi.new('const char*[?]', n)
  local keep = {}
  for i, j in ipairs(joints) do
    keep[i] = j
    names[i - 1] = j
  end
  if C.wbc_new(urdf, n, names, dt, b_ctl, b_err, 512) < 0 then
    return nil, format('%s: %s', files or urdf, ffi.string(b_err))
  end
  local self = setmetatable({
    cw = ffi.gc(b_ctl[0], C.wbc_free), name = rawget(robot, 'name') or urdf, n = n, joints = keep, dt = dt,
    ids = {}, frames = {}, names = {}, q_in = ffi.new('double[?]', n), q_out = ffi.new('double[?]', n),
    vec = ffi.new('double[64]'),
  }, Ctl)
  self:limits(robot)
  return self
end

-- The body of ROBOT (or opts.robot) with opts.dt (default: the body's control period).
function M.load(opts)
  opts = opts or {}
  return require('Config').from_description(function(robot, urdf, files)
    return M.new(robot, urdf, opts.dt or robot.period, files)
  end, opts.robot and { robot = opts.robot } or nil)
end

-- Joint limits from a robot config: `limits` (rad) and each actuator's speed (rad/s), times
-- speed_share (default 1: the whole speed).
function Ctl:limits(robot, speed_share)
  local actuators = require('Config').load('actuators', nil, { robot = robot.name })
  local n = self.n
  local lo, hi, speed = ffi.new('double[?]', n), ffi.new('double[?]', n), ffi.new('double[?]', n)
  for i, j in ipairs(self.joints) do
    local lim = robot.limits[j]
    lo[i - 1], hi[i - 1] = lim[1], lim[2]
    local act = actuators[robot.actuator[j]]
    speed[i - 1] = (act and act.speed or 1.0) * (speed_share or 1)
  end
  check(self, C.wbc_set_limits(self.cw, lo, hi, speed))
end

function Ctl:contacts(frames)
  local arr = ffi.new('const char*[?]', #frames)
  for i, f in ipairs(frames) do arr[i - 1] = f end
  check(self, C.wbc_set_contacts(self.cw, #frames, arr))
end

function Ctl:reset(q)
  for i = 1, self.n do self.q_in[i - 1] = q[i] or 0 end
  check(self, C.wbc_reset(self.cw, self.q_in))
end

-- A task: kind (M.KINDS' names), opts { frame, level, gain (1/s), max_rate, max_accel (optional) }.
function Ctl:add(name, kind, opts)
  local k = M.KINDS[kind]
  if not k then
    error(format("wbc (%s): task '%s': unknown kind '%s'", self.name, tostring(name), tostring(kind)), 2)
  end
  opts = opts or {}
  local function opt(key, default)   -- opts may be a strict config table (Lib/Config.lua)
    local v = rawget(opts, key)
    if v == nil then return default end
    return v
  end
  local id = check(self, C.wbc_task_add(self.cw, name, k, opt('frame', name), opt('level', 1), opt('gain', 1),
    opt('max_rate', 0)))
  local accel = opt('max_accel', 0)
  if accel > 0 then check(self, C.wbc_task_accel(self.cw, id, accel)) end
  self.ids[name], self.frames[name] = id, opt('frame', name)
  self.names[#self.names + 1] = name
  return id
end

function Ctl:has(name) return self.ids[name] ~= nil end

local function id_of(self, name)
  local id = self.ids[name]
  if not id then error(format("wbc (%s): no task '%s'", self.name, tostring(name)), 3) end
  return id
end

-- A task's target (a list of numbers; a posture: one angle per joint), or nil: no target.
function Ctl:target(name, t)
  local id = id_of(self, name)
  if t == nil then
    check(self, C.wbc_task_clear(self.cw, id))
    return
  end
  if type(t) ~= 'table' or #t > 64 then
    error(format("wbc (%s): task '%s': a target is a list of numbers", self.name, tostring(name)), 2)
  end
  for i = 1, #t do
    if type(t[i]) ~= 'number' then
      error(format("wbc (%s): task '%s': target[%d] is not a number", self.name, tostring(name), i), 2)
    end
    self.vec[i - 1] = t[i]
  end
  check(self, C.wbc_task_target(self.cw, id, self.vec, #t))
end

function Ctl:gain(name, g) check(self, C.wbc_task_gain(self.cw, id_of(self, name), g)) end
function Ctl:accel(name, a) check(self, C.wbc_task_accel(self.cw, id_of(self, name), a)) end
function Ctl:level(name, l) check(self, C.wbc_task_level(self.cw, id_of(self, name), l)) end

function Ctl:status(name, out)
  check(self, C.wbc_task_status_of(self.cw, id_of(self, name), b_status))
  local s = b_status
  out = out or {}
  out.kind, out.level, out.rows, out.rank = KIND_NAME[tonumber(s.kind)], s.level, s.rows, s.rank
  out.frame = self.frames[name]
  out.enabled, out.feasible = s.enabled ~= 0, s.feasible ~= 0
  out.error, out.sigma_min, out.sigma_max, out.damping = s.error, s.sigma_min, s.sigma_max, s.damping
  return out
end

-- The task names, in the order they were added: the controller's own list (kept from call to
-- call, so a tick makes no garbage; not to be changed).
function Ctl:tasks() return self.names end

-- One step: the joint angles to command (robot order) into out; returns out and how many joints a
-- limit held.
function Ctl:step(out)
  local held = check(self, C.wbc_step(self.cw, self.q_out))
  out = out or {}
  for i = 1, self.n do out[i] = self.q_out[i - 1] end
  return out, held
end

function Ctl:pose(frame)
  local rot = ffi.new('double[9]')
  check(self, C.wbc_frame_pose(self.cw, frame, self.vec, rot))
  local R = {}
  for k = 1, 9 do R[k] = rot[k - 1] end
  return { x = self.vec[0], y = self.vec[1], z = self.vec[2], R = R }
end

-- Whether the body has frame `name` (a link or joint of the URDF, or 'com').
function Ctl:has_frame(name)
  return type(name) == 'string' and C.wbc_frame_pose(self.cw, name, self.vec, nil) == 0
end

function Ctl:step_us() return C.wbc_step_us(self.cw) end
-- The floating base's pose in the stance frame: { x, y, z, qx, qy, qz, qw } (the model's).
function Ctl:base(out)
  local b = self.base7 or ffi.new('double[7]')
  self.base7 = b
  C.wbc_base(self.cw, b)
  out = out or {}
  for k = 1, 7 do out[k] = b[k - 1] end
  return out
end

-- The torso's lean bound (rad from upright; 0: none), and whether the last step held it there.
function Ctl:max_lean(rad) check(self, C.wbc_set_max_lean(self.cw, rad)) end
function Ctl:leaning() return C.wbc_leaning(self.cw) == 1 end

M.Ctl = Ctl
return M
