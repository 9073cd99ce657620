-- Kinematics of the robot (forward/inverse, camera pose, centre of mass) through LuaJIT FFI over
-- Modules/kinematics (libhrpkin.so, C++/Eigen). The geometry and masses are data: the platform's
-- `kinematics` table of the body's robot.lua (Config/robots/<ROBOT>/robot.lua).
--
--   local kin = require('kinematics')
--   local model = kin.load()                 -- ROBOT's body (default op3); or kin.new(robot_cfg, kt)
--   local q6, flags = model:leg_ik('l', x, y, z, roll, pitch, yaw, out)    -- or kin.leg_ik(model, ...)
--   local q6, flags = model:leg_ik('r', { x, y, z, roll, pitch, yaw }, out)
--   local flags = model:legs_ik(lpose, rpose, q)   -- both legs into q[joint index] (robot joint order)
--   local pose = model:leg_fk('l', q6, out)        -- { x, y, z, roll, pitch, yaw }
--   local hand = model:arm_fk('l', q3, out)        -- { x, y, z }
--   local q3, flags = model:arm_ik('l', { x, y, z }, q3)   -- q3: start guess in, solution out
--   local cam = model:head_fk(q2, out)             -- { x, y, z, R = {9} } camera in the torso frame
--   local q2, flags = model:look_at({ x, y, z }, out)      -- head angles pointing the camera there
--   local c = model:com(q, out)                    -- { x, y, z } whole-body COM, torso frame
--   local cam = model:camera_pose(q, { roll, pitch }, out)  -- { x, y, z, R = {9}, height }
--
-- Units and frames: metres, radians. Torso frame: x forward, y left, z up, origin `kinematics.origin`
-- (OP3 and DARwIn-OP: between the hip yaw axes at the hip yaw joints' height; for the OP3 the
-- origin of body_link in Config/robots/op3/op3.urdf). `model.origin` gives it in the zero-pose frame.
-- A foot pose is the pose of the foot frame (origin at the sole point below the ankle, axes
-- parallel to the torso's at the zero pose)
-- in the torso frame, as x y z roll pitch yaw with R = Rz(yaw) Ry(pitch) Rx(roll).
-- camera_pose is in the level frame: torso origin, torso roll and pitch removed (yaw ignored);
-- `height` is the camera's height above the lower sole. Camera frame: x = optical axis, z = image up.
-- Joint angles: right-hand rule about each joint's axis as given in the config (zero = zero pose).
-- Limb angle arrays are in limb order: leg = hip yaw, hip roll, hip pitch, knee, ankle pitch,
-- ankle roll; arm = shoulder pitch, shoulder roll, elbow; head = pan, tilt. Whole-body arrays
-- (`q`) are 1-based Lua tables in the robot's joint order (robot.joints).
--
-- Flags (a number, bits): kin.UNREACHABLE (out of reach: the nearest reachable solution is
-- returned), kin.JOINT_LIMIT (an angle was clamped to its limit), kin.BAD_INPUT (NaN/inf input
-- replaced by the zero-pose value). Results are never NaN.
-- Garbage: pass `out` tables to the hot calls (leg_ik, legs_ik, leg_fk, com); the C buffers are
-- allocated once at load, so such calls allocate nothing.
local ffi = require('ffi')
local native = require('native')

local type, error, tostring, format = type, error, tostring, string.format
local bor = require('bit').bor

ffi.cdef [[
typedef struct kin_desc {
  int njoint;
  const int *parent;
  const double *axis;
  const double *anchor;
  const double *mass;
  const double *com;
  const double *qmin;
  const double *qmax;
  double torso_mass;
  double torso_com[3];
  double origin[3];
  int leg[2][6];
  double sole[2][3];
  int arm[2][3];
  double hand[2][3];
  int head[2];
  double camera[3];
} kin_desc;
typedef struct kin_model kin_model;
int kin_model_create(const kin_desc *d, kin_model **out, char *err, size_t errlen);
void kin_model_destroy(kin_model *m);
int kin_njoint(const kin_model *m);
double kin_total_mass(const kin_model *m);
int kin_link_poses(const kin_model *m, const double *q, double *out);
int kin_leg_fk(const kin_model *m, int side, const double *q6, double *pose, double *rot);
int kin_arm_fk(const kin_model *m, int side, const double *q3, double *pos, double *rot);
int kin_head_fk(const kin_model *m, const double *q2, double *pos, double *rot);
int kin_camera_pose(const kin_model *m, const double *q, const double *rpy,
                    double *pos, double *rot, double *height);
int kin_com(const kin_model *m, const double *q, double *com);
int kin_leg_ik(const kin_model *m, int side, const double *pose, double *q6);
int kin_arm_ik(const kin_model *m, int side, const double *pos, double *q3);
int kin_head_look_at(const kin_model *m, const double *target, double *q2);
]]

local C = native.load('kin')

local M = {
  UNREACHABLE = 1, -- target out of reach: nearest reachable solution returned
  JOINT_LIMIT = 2, -- an angle was clamped to its joint limit
  BAD_INPUT = 4,   -- a NaN or infinite input was replaced by its zero-pose value
}

-- C buffers, allocated once: hot calls make no garbage.
local MAXJ = 64
local b_in = ffi.new('double[?]', MAXJ)
local b_out = ffi.new('double[?]', MAXJ)
local b_rot = ffi.new('double[9]')
local b_rpy = ffi.new('double[3]')
local b_h = ffi.new('double[1]')
local b_err = ffi.new('char[256]')
local b_model = ffi.new('kin_model*[1]')

local SIDES = { l = 0, left = 0, r = 1, right = 1, [0] = 0, [1] = 1 }
local LEG = { 'hip_yaw', 'hip_roll', 'hip_pitch', 'knee', 'ank_pitch', 'ank_roll' }
local ARM = { 'sho_pitch', 'sho_roll', 'el' }

local Model = {}
Model.__index = Model

local function side_of(side)
  local s = SIDES[side]
  if not s then error(format("kinematics: side must be 'l' or 'r', got %s", tostring(side)), 3) end
  return s
end

local function vec3(v, what)
  if type(v) ~= 'table' or type(v[1]) ~= 'number' or type(v[2]) ~= 'number' or type(v[3]) ~= 'number' then
    error(format('kinematics config: %s must be a table of 3 numbers', what), 3)
  end
  return v
end

-- Builds a model from a robot config (`joints` order, optional `limits`) and a kinematics table
-- (default robot.kinematics). Returns the model, or nil and a message if the C side rejects it.
function M.new(robot, kt)
  if type(robot) ~= 'table' or type(rawget(robot, 'joints')) ~= 'table' then
    error('kinematics.new: robot config with a joints list expected', 2)
  end
  kt = kt or rawget(robot, 'kinematics')
  if type(kt) ~= 'table' then error('kinematics.new: no kinematics table (robot.kinematics)', 2) end
  local names = robot.joints
  local n = #names
  if n < 1 or n > MAXJ then error('kinematics.new: 1..64 joints expected', 2) end
  local index = {}
  for i = 1, n do index[names[i]] = i - 1 end
  local parent = ffi.new('int[?]', n)
  local axis, anchor = ffi.new('double[?]', 3 * n), ffi.new('double[?]', 3 * n)
  local mass, com = ffi.new('double[?]', n), ffi.new('double[?]', 3 * n)
  local qmin, qmax = ffi.new('double[?]', n), ffi.new('double[?]', n)
  local limits = rawget(robot, 'limits')
  local jt = kt.joints
  for i = 1, n do
    local name = names[i]
    local j = jt[name]
    if type(j) ~= 'table' then error(format("kinematics config: no entry for joint '%s'", name), 2) end
    local p = rawget(j, 'parent')
    if p ~= nil and index[p] == nil then
      error(format("kinematics config: joint '%s': unknown parent '%s'", name, tostring(p)), 2)
    end
    parent[i - 1] = p and index[p] or -1
    local a, r = vec3(j.axis, name .. '.axis'), vec3(j.anchor, name .. '.anchor')
    local c = vec3(j.com, name .. '.com')
    for k = 0, 2 do
      axis[3 * (i - 1) + k], anchor[3 * (i - 1) + k], com[3 * (i - 1) + k] = a[k + 1], r[k + 1], c[k + 1]
    end
    if type(j.mass) ~= 'number' then error(format("kinematics config: joint '%s': mass missing", name), 2) end
    mass[i - 1] = j.mass
    local lim = limits and rawget(limits, name)
    qmin[i - 1] = lim and lim[1] or -math.huge
    qmax[i - 1] = lim and lim[2] or math.huge
  end
  local d = ffi.new('kin_desc')
  d.njoint, d.parent, d.axis, d.anchor, d.mass, d.com = n, parent, axis, anchor, mass, com
  d.qmin, d.qmax = qmin, qmax
  d.torso_mass = kt.torso.mass
  local tc, o, cam = vec3(kt.torso.com, 'torso.com'), vec3(kt.origin, 'origin'), vec3(kt.camera, 'camera')
  for k = 0, 2 do d.torso_com[k], d.origin[k], d.camera[k] = tc[k + 1], o[k + 1], cam[k + 1] end
  local function idx(name)
    local v = index[name]
    if v == nil then error(format("kinematics: joint '%s' not in the robot's joint list", name), 3) end
    return v
  end
  for s, pre in pairs({ [0] = 'l_', [1] = 'r_' }) do
    for k = 1, 6 do d.leg[s][k - 1] = idx(pre .. LEG[k]) end
    for k = 1, 3 do d.arm[s][k - 1] = idx(pre .. ARM[k]) end
    local sole = vec3(kt.sole[pre:sub(1, 1)], 'sole.' .. pre:sub(1, 1))
    local hand = vec3(kt.hand[pre:sub(1, 1)], 'hand.' .. pre:sub(1, 1))
    for k = 0, 2 do d.sole[s][k], d.hand[s][k] = sole[k + 1], hand[k + 1] end
  end
  d.head[0], d.head[1] = idx('head_pan'), idx('head_tilt')
  local rc = C.kin_model_create(d, b_model, b_err, 256)
  if rc ~= 0 then return nil, 'kinematics: ' .. ffi.string(b_err) end
  local m = setmetatable({
    cm = ffi.gc(b_model[0], C.kin_model_destroy),
    n = n,
    joints = names,
    index = index,
    leg_index = { [0] = {}, [1] = {} }, -- 1-based joint indices of each leg
    origin = { o[1], o[2], o[3] },
  }, Model)
  for s = 0, 1 do
    for k = 1, 6 do m.leg_index[s][k] = d.leg[s][k - 1] + 1 end
  end
  m.mass = C.kin_total_mass(m.cm)
  return m
end

-- The model of a body (opts: nil = ROBOT, or { robot = name }): its robot.lua with `kinematics`.
function M.load(opts)
  local Config = require('Config')
  local robot = Config.load('robot', nil, opts)
  local m, err = M.new(robot, rawget(robot, 'kinematics'))
  if not m then error(err, 2) end
  return m
end

local function fill_q(m, q)
  if type(q) ~= 'table' then error('kinematics: joint angles must be a table', 3) end
  for i = 1, m.n do b_in[i - 1] = q[i] or 0 end
end

-- Leg IK: (side, x, y, z, roll, pitch, yaw [, out]) or (side, {6} [, out]) -> out {6}, flags.
function Model:leg_ik(side, x, y, z, roll, pitch, yaw, out)
  local s = side_of(side)
  if type(x) == 'table' then
    out = y
    b_in[0], b_in[1], b_in[2], b_in[3], b_in[4], b_in[5] = x[1], x[2], x[3], x[4], x[5], x[6]
  else
    b_in[0], b_in[1], b_in[2], b_in[3], b_in[4], b_in[5] = x, y, z, roll, pitch, yaw
  end
  local flags = C.kin_leg_ik(self.cm, s, b_in, b_out)
  out = out or {}
  for k = 1, 6 do out[k] = b_out[k - 1] end
  return out, flags
end

-- Both legs: foot poses {6} (torso frame) -> q[joint index] for the 12 leg joints; returns the
-- flags of both legs OR-ed.
function Model:legs_ik(lpose, rpose, q)
  local flags = 0
  local cm = self.cm
  for s = 0, 1 do
    local p = s == 0 and lpose or rpose
    b_in[0], b_in[1], b_in[2], b_in[3], b_in[4], b_in[5] = p[1], p[2], p[3], p[4], p[5], p[6]
    local f = C.kin_leg_ik(cm, s, b_in, b_out)
    flags = bor(flags, f)
    local li = self.leg_index[s]
    for k = 1, 6 do q[li[k]] = b_out[k - 1] end
  end
  return flags
end

-- a limb's FK through the C function fk: n angles in, nout numbers out
local function limb_fk(model, fk, side, q, n, nout, out)
  local s = side_of(side)
  for k = 0, n - 1 do b_in[k] = q[k + 1] end
  local flags = fk(model.cm, s, b_in, b_out, nil)
  out = out or {}
  for k = 1, nout do out[k] = b_out[k - 1] end
  return out, flags
end

-- Leg FK: 6 angles -> foot pose {x, y, z, roll, pitch, yaw}, flags.
function Model:leg_fk(side, q6, out) return limb_fk(self, C.kin_leg_fk, side, q6, 6, 6, out) end

-- Arm FK: 3 angles -> hand position {x, y, z}, flags.
function Model:arm_fk(side, q3, out) return limb_fk(self, C.kin_arm_fk, side, q3, 3, 3, out) end

-- Arm IK: hand position {3} -> q3 (start guess in, solution out; zeros if nil), flags.
function Model:arm_ik(side, pos, q3)
  local s = side_of(side)
  q3 = q3 or { 0, 0, 0 }
  for k = 0, 2 do b_in[k] = pos[k + 1]; b_out[k] = q3[k + 1] end
  local flags = C.kin_arm_ik(self.cm, s, b_in, b_out)
  for k = 1, 3 do q3[k] = b_out[k - 1] end
  return q3, flags
end

local function pose_out(out, pos, rot)
  out = out or {}
  out[1], out[2], out[3] = pos[0], pos[1], pos[2]
  local R = out.R or {}
  for k = 1, 9 do R[k] = rot[k - 1] end
  out.R = R
  return out
end

-- Head FK: {pan, tilt} -> camera {x, y, z, R = {9 row-major}} in the torso frame, flags.
function Model:head_fk(q2, out)
  b_in[0], b_in[1] = q2[1], q2[2]
  local flags = C.kin_head_fk(self.cm, b_in, b_out, b_rot)
  return pose_out(out, b_out, b_rot), flags
end

-- Head angles {pan, tilt} that point the camera's optical axis at a point (torso frame), flags.
function Model:look_at(target, out)
  b_in[0], b_in[1], b_in[2] = target[1], target[2], target[3]
  local flags = C.kin_head_look_at(self.cm, b_in, b_out)
  if flags < 0 then error('kinematics.look_at: the head is not a pan (z) / tilt (y) pair', 2) end
  out = out or {}
  out[1], out[2] = b_out[0], b_out[1]
  return out, flags
end

-- Whole-body centre of mass {x, y, z} (torso frame) from all joint angles, flags.
function Model:com(q, out)
  fill_q(self, q)
  local flags = C.kin_com(self.cm, b_in, b_out)
  out = out or {}
  out[1], out[2], out[3] = b_out[0], b_out[1], b_out[2]
  return out, flags
end

-- Camera pose in the level frame from all joint angles and the torso's {roll, pitch[, yaw]}:
-- {x, y, z, R = {9}, height}, flags.
function Model:camera_pose(q, rpy, out)
  fill_q(self, q)
  b_rpy[0], b_rpy[1], b_rpy[2] = rpy[1] or 0, rpy[2] or 0, rpy[3] or 0
  local flags = C.kin_camera_pose(self.cm, b_in, b_rpy, b_out, b_rot, b_h)
  out = pose_out(out, b_out, b_rot)
  out.height = b_h[0]
  return out, flags
end

-- Pose of every link in the torso frame: { [i] = {x, y, z, R = {9}} } in joint order.
function Model:link_poses(q)
  fill_q(self, q)
  local buf = ffi.new('double[?]', 12 * self.n)
  local flags = C.kin_link_poses(self.cm, b_in, buf)
  local res = {}
  for j = 0, self.n - 1 do
    local R = {}
    for k = 1, 9 do R[k] = buf[12 * j + k - 1] end
    res[j + 1] = { buf[12 * j + 9], buf[12 * j + 10], buf[12 * j + 11], R = R }
  end
  return res, flags
end

-- Module-level forms: kin.leg_ik(model, ...) == model:leg_ik(...), and so on.
for _, name in ipairs({ 'leg_ik', 'legs_ik', 'leg_fk', 'arm_fk', 'arm_ik', 'head_fk', 'look_at', 'com',
  'camera_pose', 'link_poses' }) do
  local f = Model[name]
  M[name] = function(model, ...)
    if getmetatable(model) ~= Model then error('kinematics.' .. name .. ': model expected', 2) end
    return f(model, ...)
  end
end
M.forward_leg = M.leg_fk
M.forward_arm = M.arm_fk
Model.forward_leg = Model.leg_fk
Model.forward_arm = Model.arm_fk

return M
