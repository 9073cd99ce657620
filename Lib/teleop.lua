-- Teleoperation's key poses and their validation before motion (docs/teleoperation.md): a key pose
-- (Config/robots/<body>/keyposes/<name>.lua, its shape checked by Config/spec/keyposes.lua) gives
-- hand, pelvis and foot targets in the stance frame with a mode per limb (free: to its target; hold:
-- where it is; follow: wherever the body takes it), optionally the centre of mass's place and joints
-- set directly. A plan is a list of key poses from the robot's present joint angles: the whole-body
-- controller (Lib/wbc.lua) steps through it at the control period, its targets moving along minimum
-- jerk paths, and every sample of the resulting joint trajectory is checked before anything moves:
-- joint limits, joint speeds, self-collision (Lib/collide.lua), the centre of mass inside the support
-- polygon with a margin, the held feet not sliding, and each free limb's reach at its segment's end.
-- The checks measure the samples themselves in a rigid-body model of their own (Lib/dynamics.lua),
-- the floating base where the controller has it. Limits and margins: Config/common/teleop.lua.
--
--   local teleop = require('teleop')
--   local kp = teleop.keypose('reach')                 -- ROBOT's; { robot = 'hubo2plus' } as 2nd argument
--   local kp = teleop.keypose_file('path/to/pose.lua') -- a file outside the config (same checks)
--   local v = teleop.validator({ robot = 'hubo2plus' })
--   local plan, why = v:plan(q0, { kp, ... })          -- q0: present joint angles (robot order)
--   plan  --> { dt, n, nj, q = { {nj angles} x n }, segments = { last sample of each }, checksum, figures }
--   why   --> { reason, t, sample, segment, keypose, detail, message }   (plan nil: rejected)
--
-- Reasons: 'reach' (a free limb short of its target at its segment's end: checked first), then per
-- sample in order 'joint_limit', 'joint_speed', 'self_collision', 'com' (inside the support polygon
-- by less than the margin), 'foot_drift'. t is the first failing instant (s from the plan's start;
-- sample = t / dt + 1). A key pose naming a limb or joint the body lacks, or a foot not held, is an
-- error when it is loaded (the file and the key named).
local Config = require('Config')
local bit = require('bit')

local format, floor, sqrt, min, max = string.format, math.floor, math.sqrt, math.min, math.max

local M = {}

M.REASONS = { 'reach', 'joint_limit', 'joint_speed', 'self_collision', 'com', 'foot_drift' }
local FEET = { lfoot = true, rfoot = true }

-- ---------------------------------------------------------------------------------------------------
-- Key poses

local function keypose_error(files, key, msg) error(format("%s: key '%s' %s", files, key, msg), 0) end

-- The limbs, joints and modes against the body and the teleop config.
local function against_body(kp, files, robot, cfg)
  local joint = {}
  for _, j in ipairs(robot.joints) do joint[j] = true end
  local names = {}
  for name in pairs(cfg.limbs) do names[#names + 1] = name end
  table.sort(names)
  for name, l in pairs(kp.limbs) do
    if rawget(cfg.limbs, name) == nil then
      keypose_error(files, 'limbs.' .. name,
        format('names no limb of the teleop config (%s)', table.concat(names, ', ')))
    end
    if FEET[name] and l.mode ~= 'hold' then
      keypose_error(files, 'limbs.' .. name .. '.mode',
        "must be 'hold': a foot stays on the ground in a key pose (the walk moves the feet)")
    end
  end
  for name in pairs(FEET) do
    if kp.limbs[name] == nil then kp.limbs[name] = { mode = 'hold' } end
  end
  for j in pairs(kp.joints) do
    if not joint[j] then keypose_error(files, 'joints.' .. j, format('names no joint of the body %s', robot.name)) end
  end
  return kp
end

-- A plain copy of a checked key pose table.
local function normalise(name, files, t)
  local kp = { name = name, files = files, doc = t.doc, duration = t.duration, limbs = {},
    com = rawget(t, 'com'), joints = {} }
  for limb, l in pairs(t.limbs) do
    local pos = rawget(l, 'pos')
    kp.limbs[limb] = { mode = l.mode, pos = pos and { pos[1], pos[2], pos[3] } or nil }
  end
  if kp.com then kp.com = { kp.com[1], kp.com[2] } end
  for j, a in pairs(rawget(t, 'joints') or {}) do kp.joints[j] = a end
  return kp
end

-- Key pose `name` of the body (opts.robot, default ROBOT): errors name the file and the key.
function M.keypose(name, opts)
  if type(name) ~= 'string' or not name:match('^[%w_]+$') or #name > 31 then
    error(format("key pose: '%s' is not a key pose name (letters, digits, _; up to 31)", tostring(name)), 2)
  end
  local copts = { robot = opts and opts.robot }
  local concern = 'keyposes/' .. name
  local ok, t = pcall(Config.load, concern, nil, copts)
  if not ok then error(tostring(t), 0) end
  local files = table.concat(Config.files(concern, copts), ' + ')
  local spec = dofile(require('native').root() .. '/Config/spec/keyposes.lua')
  for k in pairs(t) do
    if spec[k] == nil then keypose_error(files, tostring(k), 'is not a key of a key pose') end
  end
  return against_body(normalise(name, files, t), files, Config.load('robot', nil, copts),
    Config.load('teleop', nil, copts))
end

-- A key pose from a file outside the config folders (a page's upload, a test's fixture), checked
-- as the config's are.
function M.keypose_file(path, opts)
  local chunk, err = loadfile(path)
  if not chunk then error(format('%s: %s', path, tostring(err)), 0) end
  setfenv(chunk, {})
  local ok, t = pcall(chunk)
  if not ok or type(t) ~= 'table' then error(format('%s: must return a table (%s)', path, tostring(t)), 0) end
  local spec = dofile(require('native').root() .. '/Config/spec/keyposes.lua')
  local keys = {}
  for k in pairs(spec) do keys[#keys + 1] = k end
  table.sort(keys)
  for _, key in ipairs(keys) do
    local want, v = spec[key], t[key]
    if type(want) == 'function' then
      local res, sub = want(v, t)
      if res ~= true then keypose_error(path, key .. (sub and '.' .. tostring(sub) or ''), tostring(res)) end
    elseif type(v) ~= want then
      keypose_error(path, key, format('must be a %s, got %s', want, type(v)))
    end
  end
  for k in pairs(t) do
    if spec[k] == nil then keypose_error(path, tostring(k), 'is not a key of a key pose') end
  end
  local copts = { robot = opts and opts.robot }
  local name = path:match('([^/]+)%.lua$') or path
  return against_body(normalise(name, path, t), path, Config.load('robot', nil, copts),
    Config.load('teleop', nil, copts))
end

-- ---------------------------------------------------------------------------------------------------
-- The checksum of a trajectory: 32-bit FNV-1a over its angles as IEEE doubles, little-endian, sample
-- after sample (what Player/Motion/teleop_link.lua recomputes over what arrived).

local ffi = require('ffi')
local b_d = ffi.new('double[1]')
local b_u8 = ffi.cast('uint8_t*', b_d)

function M.fnv1a(h, x)
  b_d[0] = x
  for k = 0, 7 do
    h = bit.bxor(h, b_u8[k])
    -- h * 16777619 mod 2^32 (16777619 = 2^24 + 403), in exact doubles
    h = bit.tobit(bit.lshift(h, 24) + bit.tobit(h * 403))
  end
  return h
end
M.FNV_START = bit.tobit(2166136261)

function M.checksum(q, n, nj)
  local h = M.FNV_START
  for i = 1, n do
    local s = q[i]
    for j = 1, nj do h = M.fnv1a(h, s[j]) end
  end
  return h
end

-- ---------------------------------------------------------------------------------------------------
-- The support polygon: the convex hull of the bottom corners of the URDF's sole* collision boxes of
-- the feet's links, in the stance frame.

local polygon = require('support_polygon')
local hull, inside = polygon.hull, polygon.inside
M.hull, M.inside = hull, inside

-- ---------------------------------------------------------------------------------------------------
-- The validator

local V = {}
V.__index = V

local function minjerk(s)
  if s >= 1 then return 1 end
  if s <= 0 then return 0 end
  return s * s * s * (10 + s * (-15 + 6 * s))
end

-- A validator of the body (opts.robot, default ROBOT): its controller, model and collision checker.
function M.validator(opts)
  opts = opts or {}
  local copts = { robot = opts.robot }
  local robot = Config.load('robot', nil, copts)
  local cfg = Config.load('teleop', nil, copts)
  local wcfg = Config.load('wbc', nil, copts)
  local actuators = Config.load('actuators', nil, copts)
  local ctl = require('wbc').load({ robot = robot.name, dt = robot.period })
  -- the controller moves the joints no faster than the checks allow
  ctl:limits(robot, cfg.check.speed_share)
  ctl:add('com', 'com_xy', cfg.solve.com)
  local p = wcfg.tasks.posture
  ctl:add('posture', 'posture', { level = p.level, gain = p.gain, max_rate = p.max_rate })
  ctl:max_lean(wcfg.max_lean)
  local self = setmetatable({ robot = robot, cfg = cfg, ctl = ctl, dt = robot.period, nj = #robot.joints,
    model = require('dynamics').load({ robot = robot.name }), limbs = {}, lo = {}, hi = {}, speed = {},
    feet = {} }, V)
  for name, l in pairs(cfg.limbs) do
    if not FEET[name] then
      local t = name == 'pelvis' and cfg.solve.pelvis or cfg.solve.hand
      ctl:add(name, 'position', { frame = l.frame, level = t.level, gain = t.gain, max_rate = t.max_rate })
      self.limbs[#self.limbs + 1] = name
    else
      self.feet[#self.feet + 1] = name
    end
  end
  table.sort(self.limbs)
  table.sort(self.feet)
  self.joint = {}
  for i, j in ipairs(robot.joints) do
    self.joint[j] = i
    self.lo[i], self.hi[i] = robot.limits[j][1], robot.limits[j][2]
    local act = actuators[robot.actuator[j]]
    self.speed[i] = (act and act.speed or 1.0) * cfg.check.speed_share
  end
  -- the soles' corners in their links' frames
  local _, urdf_path = Config.description({ robot = robot.name })
  local f = assert(io.open(urdf_path, 'r'))
  local urdf = f:read('*a')
  f:close()
  self.soles = {}
  for _, name in ipairs(self.feet) do
    local link = rawget(cfg.limbs[name], 'link')
    if not link then
      error(format("Config/common/teleop.lua: key 'limbs.%s.link' must name the foot's link", name), 0)
    end
    self.soles[name] = { link = link, corners = polygon.sole_corners(urdf, link, urdf_path) }
  end
  -- self-collision: links a few joints apart and the pairs touching at the zero pose are the boxes'
  -- approximation
  self.col = require('collide').load({ robot = robot.name })
  self.col:margin(cfg.check.collision_margin)
  local zero = {}
  for i = 1, self.nj do zero[i] = 0 end
  self.ignored = self.col:ignore_near(cfg.check.collision_skip_joints) + self.col:ignore_at(zero)
  return self
end

-- The support polygon of the feet where the model has them (stance frame).
local function support(self)
  local pts = {}
  for _, name in ipairs(self.feet) do
    local s = self.soles[name]
    local p = self.model:pose(s.link)
    local R = p.R
    for _, c in ipairs(s.corners) do
      pts[#pts + 1] = { p[1] + R[1] * c[1] + R[2] * c[2] + R[3] * c[3], p[2] + R[4] * c[1] + R[5] * c[2] + R[6] * c[3] }
    end
  end
  return hull(pts)
end

local function dist3(a, b) return sqrt((a[1] - b[1]) ^ 2 + (a[2] - b[2]) ^ 2 + (a[3] - b[3]) ^ 2) end

local function copy(t, n)
  local o = {}
  for i = 1, n do o[i] = t[i] end
  return o
end

-- Solves and checks the key poses `kps` from joint angles q0; see the header.
function V:plan(q0, kps)
  local ctl, cfg, dt, nj, model = self.ctl, self.cfg, self.dt, self.nj, self.model
  local ck = cfg.check
  local feet = {}
  for i, name in ipairs(self.feet) do feet[i] = cfg.limbs[name].frame end
  ctl:contacts(feet)
  ctl:reset(q0)
  local base = ctl:base()
  model:set(q0, base)
  local anchors = {}
  for _, name in ipairs(self.feet) do
    local p = model:pose(cfg.limbs[name].frame)
    anchors[name] = { p[1], p[2], p[3] }
  end
  local poly = support(self)
  local plan = { dt = dt, nj = nj, q = {}, segments = {}, figures = { com_margin = math.huge, reach = 0,
    speed_share = 0, foot_drift = 0, collide_us = 0, solve_us = 0 } }
  local fig = plan.figures
  local override = {}     -- joint index -> angle set directly (kept until another key pose sets it)
  local prev = copy(q0, nj)
  local n = 0
  local why

  local function reject(reason, seg, detail)
    local t = (n - 1) * dt
    why = { reason = reason, t = t, sample = n, segment = seg, keypose = kps[seg] and kps[seg].name, detail = detail }
    why.message = format("key pose '%s' (segment %d): %s at t = %.3f s (sample %d): %s", tostring(why.keypose), seg,
      reason, t, n, detail)
    return nil, why
  end

  -- The checks of one sample (q: the angles, seg: its segment, b: the floating base where the
  -- controller has it): a failure sets `why`.
  local function check_sample(q, seg, b)
    for i = 1, nj do
      local a = q[i]
      if a ~= a or a < self.lo[i] + ck.limit_margin - 1e-9 or a > self.hi[i] - ck.limit_margin + 1e-9 then
        return reject('joint_limit', seg, format('%s at %.3f rad, its range %.3f .. %.3f', self.robot.joints[i], a,
          self.lo[i], self.hi[i]))
      end
      local rate = math.abs(a - prev[i]) / dt
      fig.speed_share = max(fig.speed_share, rate / self.speed[i] * ck.speed_share)
      if rate > self.speed[i] * (1 + 1e-6) then
        return reject('joint_speed', seg, format('%s at %.2f rad/s, its bound %.2f rad/s', self.robot.joints[i], rate,
          self.speed[i]))
      end
    end
    local hits, la, lb = self.col:check(q)
    fig.collide_us = fig.collide_us + self.col:check_us()
    if hits > 0 then return reject('self_collision', seg, format('%s against %s (%d pairs)', la, lb, hits)) end
    model:set(q, b)
    local c = model:com()
    local m = inside(poly, c[1], c[2])
    fig.com_margin = min(fig.com_margin, m)
    if m < ck.com_margin then
      return reject('com', seg, format('centre of mass at (%.3f, %.3f) m, %.1f mm inside the support polygon '
        .. '(needs %.1f mm)', c[1], c[2], m * 1e3, ck.com_margin * 1e3))
    end
    for _, name in ipairs(self.feet) do
      local d = dist3(model:pose(cfg.limbs[name].frame), anchors[name])
      fig.foot_drift = max(fig.foot_drift, d)
      if d > ck.foot_drift then
        return reject('foot_drift', seg, format('%s moved %.1f mm (bound %.1f mm)', name, d * 1e3, ck.foot_drift * 1e3))
      end
    end
  end

  -- the start itself: a statically stable, collision-free pose inside the limits
  n = 1
  plan.q[1] = copy(q0, nj)
  check_sample(plan.q[1], 1, base)
  if why then return nil, why end

  local t0 = os.clock()
  for seg, kp in ipairs(kps) do
    local steps = max(1, floor(kp.duration / dt + 0.5))
    local moving = max(1, floor(steps * cfg.solve.share + 0.5))
    -- where each limb starts, its target; the centre of mass's; the joints set directly
    local from, to = {}, {}
    for _, name in ipairs(self.limbs) do
      local l = kp.limbs[name]
      local mode = l and l.mode or 'follow'
      if mode == 'follow' then
        ctl:target(name, nil)
      else
        local p = ctl:pose(cfg.limbs[name].frame)
        from[name] = { p.x, p.y, p.z }
        to[name] = mode == 'free' and l.pos or from[name]
      end
    end
    local c = ctl:pose('com')
    local com_from, com_to = { c.x, c.y }, kp.com or { 0, 0 }
    ctl:target('posture', prev)
    local jfrom = {}
    for j, a in pairs(kp.joints) do
      local i = self.joint[j]
      jfrom[i] = prev[i]
      override[i] = a
    end
    local tgt, bases, first = {}, {}, n + 1
    for k = 1, steps do
      local s = minjerk(k / moving)
      for name, a in pairs(from) do
        local b = to[name]
        tgt[1], tgt[2], tgt[3] = a[1] + s * (b[1] - a[1]), a[2] + s * (b[2] - a[2]), a[3] + s * (b[3] - a[3])
        ctl:target(name, tgt)
      end
      ctl:target('com', { com_from[1] + s * (com_to[1] - com_from[1]), com_from[2] + s * (com_to[2] - com_from[2]) })
      local q = ctl:step({})
      for i, a in pairs(override) do
        local f = jfrom[i]
        q[i] = f and f + s * (a - f) or a
      end
      n = n + 1
      plan.q[n] = q
      bases[n - first + 1] = ctl:base()
    end
    -- the key pose solved: each free limb's distance from its target in the model of the segment's
    -- last sample (out of reach is the key pose's fault, whatever happens on the way)
    model:set(plan.q[n], bases[#bases])
    for _, name in ipairs(self.limbs) do
      local l = kp.limbs[name]
      if l and l.mode == 'free' then
        local d = dist3(model:pose(cfg.limbs[name].frame), l.pos)
        fig.reach = max(fig.reach, d)
        if d > ck.reach then
          return reject('reach', seg, format('%s %.1f mm from its target (%.3f, %.3f, %.3f) (bound %.1f mm)', name,
            d * 1e3, l.pos[1], l.pos[2], l.pos[3], ck.reach * 1e3))
        end
      end
    end
    -- then the way there, sample after sample
    local last = n
    for m = first, last do
      n = m
      check_sample(plan.q[m], seg, bases[m - first + 1])
      if why then return nil, why end
      prev = plan.q[m]
    end
    plan.segments[seg] = n
  end
  fig.solve_us = (os.clock() - t0) * 1e6
  plan.n = n
  plan.checksum = M.checksum(plan.q, n, nj)
  return plan
end

M.Validator = V
return M
