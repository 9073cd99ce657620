-- Kinematics of the robot (forward/inverse, camera pose, centre of mass) through LuaJIT FFI over
-- Modules/kinematics (libhrpkin.so, C++/Eigen). The model is built from the body's description,
-- the URDF that robot.lua's `description` names (the same file the simulator reads), plus
-- robot.lua's joint order (`joints`) and named chains (`chains`):
--
--   chains = { lleg = { tip = 'l_sole' }, rleg = ..., larm = { joints = {...}, tip = 'l_hand' },
--              rarm = ..., head = { tip = 'camera_link' } }
--
-- Chain names: lleg/rleg (6 joints: hip yaw, roll, pitch, knee, ankle pitch, ankle roll; analytic
-- IK; a shank off the hip centre along the pitch axes is allowed), larm/rarm (any number of joints;
-- damped least squares IK), head (pan, tilt; or two horizontal tilt axes, such as the Hubo's neck,
-- whose look-at is solved numerically within their limits). `joints` lists
-- the chain's joints from its base to its tip (default: the group of the same name); `tip` is a
-- frame (or link) of the URDF on the chain's last link, or for an arm or the head on a link below it
-- (the HOAP-3's neck roll between the tilt and the camera: the joints between take their angles from
-- the trailing `q`, as the joints above the chain do). Every chain is optional; a function of a
-- chain the body lacks raises an error.
--
--   local kin = require('kinematics')
--   local model = kin.load()                 -- ROBOT's body (default op3); kin.load({ robot = 'darwin' })
--   local q6, flags = model:leg_ik('l', x, y, z, roll, pitch, yaw, out)    -- or kin.leg_ik(model, ...)
--   local q6, flags = model:leg_ik('r', { x, y, z, roll, pitch, yaw }, out [, q])
--   local flags = model:legs_ik(lpose, rpose, q)   -- both legs into q[joint index] (robot joint order)
--   local pose = model:leg_fk('l', q6, out [, q])  -- { x, y, z, roll, pitch, yaw }
--   local hand = model:arm_fk('l', qn, out [, q])  -- { x, y, z }; qn: the arm chain's n angles
--   local qn, flags = model:arm_ik('l', { x, y, z }, qn [, q])   -- qn: start guess in, solution out
--   local cam = model:head_fk(q2, out [, q])       -- { x, y, z, R = {9} } camera in the torso frame
--   local q2, flags = model:look_at({ x, y, z }, out [, q])      -- head angles pointing the camera there
--   local c = model:com(q, out)                    -- { x, y, z } whole-body COM, torso frame
--   local cam = model:camera_pose(q, { roll, pitch }, out)  -- { x, y, z, R = {9}, height }
--   local a = model:axis('l_knee')                 -- { x, y, z } joint axis, torso frame, zero pose
--   local lo, hi = model:limits('l_knee')          -- rad, the URDF's limits
--
-- Units and frames: metres, radians. Torso frame: the URDF's root link frame (x forward, y left,
-- z up; for the OP3 and the DARwIn-OP between the hip yaw axes at their height). `model.origin`
-- = { 0, 0, height of the torso origin above the soles at the zero pose }. A foot pose is the pose
-- of the leg's tip frame (origin on the sole below the ankle, axes the torso's at the zero pose)
-- in the torso frame, as x y z roll pitch yaw with R = Rz(yaw) Ry(pitch) Rx(roll). camera_pose is
-- in the level frame: torso origin, torso roll and pitch removed (yaw ignored); `height` is the
-- camera's height above the lower sole. Camera frame (the head's tip): x = optical axis, z =
-- image up, whatever the camera's pitch at the zero pose. Joint angles: right-hand rule about
-- each joint's URDF axis (zero = zero pose). Chain angle arrays are in chain order; whole-body
-- arrays (`q`) are 1-based Lua tables in the robot's joint order (robot.joints, the bus order,
-- independent of the tree). The optional trailing `q` of a chain function gives the angles of the
-- joints above the chain (a waist); without it they are 0.
--
-- Flags (a number, bits): kin.UNREACHABLE (out of reach: the nearest reachable solution is
-- returned), kin.JOINT_LIMIT (an angle was clamped to its limit), kin.BAD_INPUT (NaN/inf input
-- replaced by the zero-pose value). Results are never NaN.
-- Garbage: pass `out` tables to the hot calls (leg_ik, legs_ik, leg_fk, com); the C buffers are
-- allocated once at load, so such calls allocate nothing.
local ffi = require('ffi')
local native = require('native')

local type, error, tostring, format, pairs, ipairs = type, error, tostring, string.format, pairs, ipairs
local bor = require('bit').bor

native.cdef('kinematics')   -- Modules/kinematics/kinematics.h

local C = native.load('kin')

local M = {
  UNREACHABLE = 1, -- target out of reach: nearest reachable solution returned
  JOINT_LIMIT = 2, -- an angle was clamped to its joint limit
  BAD_INPUT = 4,   -- a NaN or infinite input was replaced by its zero-pose value
}

local LEG, ARM, HEAD = 0, 1, 2
-- chain name -> kind, side
local CHAINS = { lleg = { LEG, 0 }, rleg = { LEG, 1 }, larm = { ARM, 0 }, rarm = { ARM, 1 }, head = { HEAD, 0 } }

-- C buffers, allocated once: hot calls make no garbage.
local MAXJ = 64
local b_in = ffi.new('double[?]', MAXJ)
local b_out = ffi.new('double[?]', MAXJ)
local b_q = ffi.new('double[?]', MAXJ)
local b_rot = ffi.new('double[9]')
local b_rpy = ffi.new('double[3]')
local b_h = ffi.new('double[1]')
local b_lo, b_hi = ffi.new('double[1]'), ffi.new('double[1]')
local b_err = ffi.new('char[512]')
local b_model = ffi.new('kin_model*[1]')
local b_idx = ffi.new('int[?]', MAXJ)

local SIDES = { l = 0, left = 0, r = 1, right = 1, [0] = 0, [1] = 1 }

local Model = {}
Model.__index = Model

local function side_of(side)
  local s = SIDES[side]
  if not s then error(format("kinematics: side must be 'l' or 'r', got %s", tostring(side)), 3) end
  return s
end

-- The C array of whole-body angles (nil -> NULL: all 0).
local function qbase(m, q)
  if q == nil then return nil end
  for i = 1, m.n do b_q[i - 1] = q[i] or 0 end
  return b_q
end

local function check(m, rc, what)
  if rc == -3 then error(format('kinematics: %s has no %s chain (robot.lua chains)', m.name, what), 3) end
  if rc < 0 then error(format('kinematics: %s: bad argument (%d)', what, rc), 3) end
  return rc
end

-- Builds a model. robot: a robot config (joints, chains, groups); urdf: path of its description;
-- config: its name for messages. Returns the model, or nil and a message naming the file and the
-- element (unknown joint, a URDF joint missing from joints or the reverse, a chain the IK cannot serve).
function M.new(robot, urdf, config)
  config = config or 'robot config'
  if type(robot) ~= 'table' or type(rawget(robot, 'joints')) ~= 'table' then
    error('kinematics.new: robot config with a joints list expected', 2)
  end
  if type(urdf) ~= 'string' then error('kinematics.new: path of the URDF expected', 2) end
  local names = robot.joints
  local n = #names
  if n < 1 or n > MAXJ then return nil, format('%s: 1..%d joints expected', config, MAXJ) end
  local keep = { names } -- Lua strings the C pointers point into, alive during the call
  local cjoints = ffi.new('const char*[?]', n)
  for i = 1, n do cjoints[i - 1] = names[i] end
  local chains = rawget(robot, 'chains') or {}
  local groups = rawget(robot, 'groups') or {}
  local list = {}
  for name in pairs(chains) do list[#list + 1] = name end
  table.sort(list)
  local cchains = ffi.new('kin_chain_spec[?]', math.max(#list, 1))
  for i, name in ipairs(list) do
    local c, kind = chains[name], CHAINS[name]
    if not kind then
      return nil, format("%s: chains.%s: unknown chain (lleg, rleg, larm, rarm, head)", config, tostring(name))
    end
    if type(c) ~= 'table' or type(rawget(c, 'tip')) ~= 'string' then
      return nil, format('%s: chains.%s: needs tip = a frame of the description', config, name)
    end
    local js = rawget(c, 'joints') or rawget(groups, name)
    if type(js) ~= 'table' or #js == 0 then
      return nil, format('%s: chains.%s: no joints (and no group %s)', config, name, name)
    end
    local cj = ffi.new('const char*[?]', #js)
    for k = 1, #js do cj[k - 1] = js[k] end
    keep[#keep + 1], keep[#keep + 2] = cj, js
    local s = cchains[i - 1]
    s.name, s.kind, s.side, s.n, s.joints, s.tip = name, kind[1], kind[2], #js, cj, c.tip
  end
  local spec = ffi.new('kin_spec')
  spec.urdf, spec.config, spec.njoint, spec.joints = urdf, config, n, cjoints
  spec.nchain, spec.chains = #list, cchains
  local rc = C.kin_model_load(spec, b_model, b_err, 512)
  assert(#keep > 0) -- the strings and arrays it holds stay referenced through the call
  if rc ~= 0 then return nil, 'kinematics: ' .. ffi.string(b_err) end
  local index = {}
  for i = 1, n do index[names[i]] = i - 1 end
  local m = setmetatable({
    cm = ffi.gc(b_model[0], C.kin_model_destroy),
    name = rawget(robot, 'name') or config,
    file = urdf,
    n = n,
    joints = names,
    index = index,  -- joint name -> 0-based index
    chain_index = {}, -- chain name -> { 1-based joint indices }
    leg_index = { [0] = {}, [1] = {} }, -- 1-based joint indices of each leg
    arm_n = { [0] = 0, [1] = 0 },
  }, Model)
  for name, kind in pairs(CHAINS) do
    local k = C.kin_chain_joints(m.cm, kind[1], kind[2], b_idx)
    if k > 0 then
      local t = {}
      for j = 1, k do t[j] = b_idx[j - 1] + 1 end
      m.chain_index[name] = t
      if kind[1] == LEG then m.leg_index[kind[2]] = t end
      if kind[1] == ARM then m.arm_n[kind[2]] = k end
    end
  end
  m.mass = C.kin_total_mass(m.cm)
  local h = 0
  if m.chain_index.lleg then h = -m:leg_fk('l', { 0, 0, 0, 0, 0, 0 })[3] end
  m.origin = { 0, 0, h }
  return m
end

-- The model of a body (opts: nil = ROBOT, or { robot = name }): its robot.lua and description.
function M.load(opts) return require('Config').from_description(M.new, opts) end

local function fill_q(m, q)
  if type(q) ~= 'table' then error('kinematics: joint angles must be a table', 3) end
  for i = 1, m.n do b_in[i - 1] = q[i] or 0 end
end

local function joint_of(m, name)
  local j = m.index[name]
  if not j then error(format("kinematics: %s has no joint '%s'", m.name, tostring(name)), 3) end
  return j
end

-- Joint axis in the torso frame at the zero pose: { x, y, z } (unit).
function Model:axis(name, out)
  C.kin_joint_info(self.cm, joint_of(self, name), b_out, nil, nil)
  out = out or {}
  out[1], out[2], out[3] = b_out[0], b_out[1], b_out[2]
  return out
end

-- Joint limits (rad) of the description: lo, hi.
function Model:limits(name)
  C.kin_joint_info(self.cm, joint_of(self, name), b_out, b_lo, b_hi)
  return b_lo[0], b_hi[0]
end

-- Leg IK: (side, x, y, z, roll, pitch, yaw [, out]) or (side, {6} [, out [, q]]) -> out {6}, flags.
function Model:leg_ik(side, x, y, z, roll, pitch, yaw, out)
  local s = side_of(side)
  local qb
  if type(x) == 'table' then
    out, qb = y, qbase(self, z)
    b_in[0], b_in[1], b_in[2], b_in[3], b_in[4], b_in[5] = x[1], x[2], x[3], x[4], x[5], x[6]
  else
    b_in[0], b_in[1], b_in[2], b_in[3], b_in[4], b_in[5] = x, y, z, roll, pitch, yaw
  end
  local flags = check(self, C.kin_leg_ik(self.cm, s, b_in, qb, b_out), 'leg')
  out = out or {}
  for k = 1, 6 do out[k] = b_out[k - 1] end
  return out, flags
end

-- Both legs: foot poses {6} (torso frame) -> q[joint index] for the 12 leg joints (the other
-- joints of q place the legs' bases); returns the flags of both legs OR-ed.
function Model:legs_ik(lpose, rpose, q)
  local flags = 0
  local cm, qb = self.cm, qbase(self, q)
  for s = 0, 1 do
    local p = s == 0 and lpose or rpose
    b_in[0], b_in[1], b_in[2], b_in[3], b_in[4], b_in[5] = p[1], p[2], p[3], p[4], p[5], p[6]
    local f = check(self, C.kin_leg_ik(cm, s, b_in, qb, b_out), 'leg')
    flags = bor(flags, f)
    local li = self.leg_index[s]
    for k = 1, 6 do q[li[k]] = b_out[k - 1] end
  end
  return flags
end

-- a limb's FK through the C function fk: n angles in, nout numbers out
local function limb_fk(model, fk, what, s, q, n, nout, out, qall)
  for k = 0, n - 1 do b_in[k] = q[k + 1] or 0 end
  local flags = check(model, fk(model.cm, s, b_in, qbase(model, qall), b_out, nil), what)
  out = out or {}
  for k = 1, nout do out[k] = b_out[k - 1] end
  return out, flags
end

-- Leg FK: 6 angles -> foot pose {x, y, z, roll, pitch, yaw}, flags.
function Model:leg_fk(side, q6, out, q)
  return limb_fk(self, C.kin_leg_fk, 'leg', side_of(side), q6, 6, 6, out, q)
end

-- Arm FK: the arm chain's n angles -> hand position {x, y, z}, flags.
function Model:arm_fk(side, qn, out, q)
  local s = side_of(side)
  return limb_fk(self, C.kin_arm_fk, 'arm', s, qn, self.arm_n[s], 3, out, q)
end

-- Arm IK: hand position {3} -> qn (start guess in, solution out; zeros if nil), flags.
function Model:arm_ik(side, pos, qn, q)
  local s = side_of(side)
  local n = self.arm_n[s]
  qn = qn or {}
  for k = 0, 2 do b_in[k] = pos[k + 1] end
  for k = 0, n - 1 do b_out[k] = qn[k + 1] or 0 end
  local flags = check(self, C.kin_arm_ik(self.cm, s, b_in, qbase(self, q), b_out), 'arm')
  for k = 1, n do qn[k] = b_out[k - 1] end
  return qn, flags
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
function Model:head_fk(q2, out, q)
  b_in[0], b_in[1] = q2[1], q2[2]
  local flags = check(self, C.kin_head_fk(self.cm, b_in, qbase(self, q), b_out, b_rot), 'head')
  return pose_out(out, b_out, b_rot), flags
end

-- Head angles {pan, tilt} that point the camera's optical axis at a point (torso frame), flags.
function Model:look_at(target, out, q)
  b_in[0], b_in[1], b_in[2] = target[1], target[2], target[3]
  local flags = check(self, C.kin_head_look_at(self.cm, b_in, qbase(self, q), b_out), 'head')
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
  local flags = check(self, C.kin_camera_pose(self.cm, b_in, b_rpy, b_out, b_rot, b_h), 'head')
  out = pose_out(out, b_out, b_rot)
  out.height = b_h[0]
  return out, flags
end

-- Pose of every link in the torso frame: { [i] = {x, y, z, R = {9}} } in joint order (the link a
-- joint moves; its frame: the torso's axes at the zero pose and the torso origin, carried along).
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
  'camera_pose', 'link_poses', 'axis', 'limits' }) do
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
