-- The motion controller: one tick = read sensors, run the motion state machine, produce joint
-- commands and hardness. Independent of shm (Player/Motion/main.lua feeds it), so it can be
-- driven by tests and benchmarks directly.
--
-- States (Lib/Motion.lua's STATES, one small file each in Player/Motion/states/): relax, sit,
-- stance, walk, kick_left, kick_right, falling, standup_front, standup_back, wbc, pattern, touch, teleop.
-- Requests (relax, sit, stand, walk, kick_left, kick_right, wbc, pattern, touch, teleop) are wishes: `ctl.want`
-- holds the last one and the states move towards it (relax at once from anywhere; the rest through
-- stance). 'pattern' takes a trajectory file (Lib/trajectory.lua), read when it is asked for: ctl.pattern.
--
-- Who drives a joint (as ROBOTIS' motion modules: each owns the joints it drives): every tick
-- starts from the hold pose (ctl.q, ctl.h: the last commands, or what the actuators held when the
-- process started). A state declares the joints it owns in its module's `owns`: a list of roles
-- (legs: the leg IK's joints; arms: the joints the walk config's `arms` names; head: the first two
-- joints of the body's `head` group, moved by motion.head_command; all: every joint) or a
-- function(ctl) returning joint indices (the keyframe states: the joints their files name). After
-- the state's update only its joints keep what it wrote; every other joint holds, so a joint no
-- state owns (a waist) keeps its position and can be commanded from outside. A joint a caller has
-- taken (ctl.taken[i], Body.set_command & co. while motion drives it; see Player/Motion/main.lua)
-- gets the caller's command (ctl.taken_q[i]) instead, until released. ctl.write[i] says which
-- joints the process writes this tick; ctl.owner[i]: 0 held, 1 the state, 2 a caller.
local fsm = require('fsm')
local Motion = require('Motion')
local Walk = require('Motion.walk')
local WalkPreview = require('Motion.walk_preview')
local keyframe = require('Motion.keyframe')
local Kick = require('Motion.kick')
local WalkKick = require('Motion.walk_kick')
local balance = require('Motion.balance')
local capture = require('Motion.capture')
local step_adjust = require('Motion.step_adjust')
local trajectory = require('trajectory')

local abs = math.abs

local M = {}
local Ctl = {}
Ctl.__index = Ctl

local TRANSITIONS = {
  relax = { sit = 'sit', stand = 'stance', walk = 'stance', kick_left = 'stance', kick_right = 'stance' },
  sit = { stand = 'stance', walk = 'stance', kick_left = 'stance', kick_right = 'stance' },
  stance = { sit = 'sit', walk = 'walk', kick_left = 'kick_left', kick_right = 'kick_right', wbc = 'wbc',
    pattern = 'pattern', touch = 'touch', teleop = 'teleop', fall = 'falling' },
  walk = { done = 'stance', fall = 'falling' },
  kick_left = { done = 'stance', fall = 'falling' },
  kick_right = { done = 'stance', fall = 'falling' },
  falling = { front = 'standup_front', back = 'standup_back', stand = 'stance' },
  standup_front = { done = 'stance', fall = 'falling' },
  standup_back = { done = 'stance', fall = 'falling' },
  wbc = { done = 'stance', fall = 'falling' },
  pattern = { done = 'stance', fall = 'falling' },
  touch = { done = 'stance', fall = 'falling' },
  teleop = { done = 'stance', fall = 'falling' },
  ['*'] = { relax = 'relax' },
}
-- states in which a fall is watched for (the stand-ups check the result themselves)
local WATCH_FALL = { stance = true, walk = true, kick_left = true, kick_right = true, wbc = true, pattern = true,
  touch = true, teleop = true }

local ROLES = { legs = true, arms = true, head = true, all = true }

-- The joints of each role, from the robot data (robot.lua's groups, the walk config's arms).
local function roles(c, robot)
  local w, n = c.walk, c.n
  local r = { legs = {}, arms = {}, head = {}, all = {} }
  for i = 1, n do r.all[i] = i end
  for _, side in ipairs({ Walk.LEFT, Walk.RIGHT }) do
    for _, i in ipairs(w.legs[side]) do r.legs[#r.legs + 1] = i end
  end
  table.sort(r.legs)
  for k, i in ipairs(w.arm_joints) do r.arms[k] = i end
  local head = robot.groups.head
  for k = 1, math.min(2, #head) do
    r.head[k] = c.ji[head[k]] or error(string.format("robot config: group 'head' names unknown joint '%s'",
      tostring(head[k])), 3)
  end
  return r
end

-- The body as keyframe files see it (Player/Motion/keyframe.lua): joint indices by name and the
-- mirror twin of a left-side joint with the sign from the two axes. ji: indices by name (optional).
function M.keyframe_body(robot, model, ji)
  if not ji then
    ji = {}
    for i, name in ipairs(robot.joints) do ji[name] = i end
  end
  local function mirror(name)
    local base = type(name) == 'string' and name:match('^l_(.+)$')
    if not base then return nil, "only left-side joints (l_...) are mirrored" end
    local twin = 'r_' .. base
    if not ji[twin] then return nil, "the body has no joint '" .. twin .. "' to mirror it onto" end
    local a, b = model:axis(name), model:axis(twin)
    -- the mirror image (through the x-z plane) of a rotation about a is one about (-ax, ay, -az)
    local d = -a[1] * b[1] + a[2] * b[2] - a[3] * b[3]
    if abs(abs(d) - 1) > 1e-6 then
      return nil, string.format("the axes of '%s' and '%s' are not mirror images", name, twin)
    end
    return ji[twin], d > 0 and 1 or -1, twin
  end
  return { index = ji, mirror = mirror }
end

-- The walk engine the walk config's `engine` names (read when the motion process starts).
local ENGINES = { analytic = Walk, preview = WalkPreview }
function M.walk_engine(params, files)
  local name = params.engine
  local engine = ENGINES[name]
  if not engine then
    error(string.format("%s: key 'engine' must be 'analytic' or 'preview', got '%s'", files or 'walk config',
      tostring(name)), 2)
  end
  return engine
end

-- The walk's extensions (Player/Motion/walk.lua), in their order: the F/T balance's COM shift, the
-- capture point's error, the step adjustment on it, the kick out of the walk. ext: { balance,
-- capture, step_adjust, walk_kick } (any may be nil).
function M.extend_walk(w, ext)
  for _, e in ipairs({ ext.balance or false, ext.capture or false, ext.step_adjust or false,
    ext.walk_kick or false }) do
    if e then w:extend(e) end
  end
  return w
end

-- opts: robot (Config robot table), params (walk config, read live), model (kinematics),
-- initial (state name, default 'stance'), walk_files (the walk config's files, for errors).
function M.new(opts)
  local robot, params = opts.robot, opts.params
  local n = #robot.joints
  local c = setmetatable({
    robot = robot, p = params, model = opts.model, n = n,
    q = {}, h = {}, pos = {}, gyro = { 0, 0, 0 }, angle = { 0, 0, 0 }, acc = { 0, 0, 9.81 }, ft = {},
    t = 0, dt = robot.period, want = 'stand', falls = 0, fall_time = -1, tilt = 0,
    vel_cmd = { 0, 0, 0 }, head = { 0, 0 },
    hold_q = {}, hold_h = {}, owned = {}, taken = {}, taken_q = {}, write = {}, owner = {}, touch = {},
    owns_cache = {}, data = {},
  }, Ctl)
  for i = 1, n do
    c.q[i], c.h[i], c.pos[i], c.taken_q[i] = 0, 0, 0, 0
    c.owned[i], c.taken[i], c.write[i], c.owner[i] = false, false, false, 0
  end
  for k = 1, 24 do c.ft[k] = 0 end
  -- the feet's point pressure sensors (dcm.sensor.foot_pressure, robot.lua foot_pressure)
  c.press = {}
  local fp = rawget(robot, 'foot_pressure') -- optional (a Config table errs on a missing key)
  for k = 1, fp and #fp.lfoot.points + #fp.rfoot.points or 0 do c.press[k] = 0 end
  c.sensors = { gyro = c.gyro, position = c.pos, angle = c.angle, acc = c.acc, ft = c.ft, press = c.press }
  c.walk = M.walk_engine(params, opts.walk_files).new(params, opts.model):bind(robot, opts.walk_files)
  c.balance = balance.new(params, robot)
  c.kick = Kick.new(c.walk)
  c.walk_kick = WalkKick.new(params)
  c.capture = capture.new()
  c.step_adjust = step_adjust.new(c.capture)
  M.extend_walk(c.walk, c)
  c.ji = c.walk.ji
  c.roles = roles(c, robot)
  -- keyframe motions are checked at start: a bad file stops the process with the file named
  c.keyframes = {}
  local body = M.keyframe_body(robot, opts.model, c.ji)
  -- (a body that cannot stand itself up, walk config fallPolicy.standup = false, has no stand-ups)
  local policy = params.fallPolicy
  local standup = not (policy and policy.standup == false)
  for _, name in ipairs(standup and { 'sit', 'standup_front', 'standup_back' } or { 'sit' }) do
    c.keyframes[name] = keyframe.load(name, body, robot.name)
  end
  c.machine = fsm.new({
    name = 'motion',
    states = Motion.STATES,
    load = function(s) return require('Motion.states.' .. s) end,
    initial = opts.initial or 'stance',
    transitions = TRANSITIONS,
    on_transition = function(_, from, to) c:hand_over(from, to) end,
  })
  for _, s in ipairs(Motion.STATES) do c:joints_of(s) end -- a bad `owns` fails here
  return c
end

-- The joints state `s` owns (1-based indices, ascending; see the header).
function Ctl:joints_of(s)
  local list = self.owns_cache[s]
  if list then return list end
  local owns = self.machine.modules[s].owns
  local set = {}
  if type(owns) == 'function' then
    for _, i in ipairs(owns(self)) do set[i] = true end
  elseif type(owns) == 'table' then
    for _, role in ipairs(owns) do
      if not ROLES[role] then
        error(string.format("motion state '%s': owns unknown role '%s'", s, tostring(role)), 0)
      end
      for _, i in ipairs(self.roles[role]) do set[i] = true end
    end
  else
    error(string.format("motion state '%s': no `owns` (the joints it drives)", s), 0)
  end
  list = {}
  for i in pairs(set) do list[#list + 1] = i end
  table.sort(list)
  self.owns_cache[s] = list
  return list
end

-- A state change: the new state's joints become owned, the rest held. Coming out of relax (or at
-- start), held joints stiffen to hardnessHold at their last command: relax let them go.
function Ctl:hand_over(from, to)
  self.prev = from
  local owned = self.owned
  for i = 1, self.n do owned[i] = false end
  local own = self:joints_of(to)
  for _, i in ipairs(own) do owned[i] = true end
  self.own = own
  if (from == nil or from == 'relax') and to ~= 'relax' then
    local h = self.p.hardnessHold
    for i = 1, self.n do
      if not owned[i] then self.h[i], self.hold_h[i], self.touch[i] = h, h, true end
    end
  end
end

-- Takes in what others did since the last tick (0-based arrays, as in shm): the commands and
-- hardness of the joints the current state does not drive (the hold pose follows them), and which
-- joints a caller took, with the caller's commands.
function Ctl:sync(command, hardness, taken, taken_command)
  local owned = self.owned
  for i = 1, self.n do
    local tk = taken[i - 1] ~= 0
    self.taken[i] = tk
    if tk then self.taken_q[i] = taken_command[i - 1] end
    if not owned[i] or tk then
      if not tk then self.q[i] = command[i - 1] end
      self.h[i] = hardness[i - 1]
    end
  end
end

-- The joints the state `want` would own (a request releases the caller's hold on them).
function Ctl:needs(request)
  local s = Motion.REQUESTS[request]
  return s and self:joints_of(s) or {}
end

-- Per-activation data of a state (on the controller, not in the state's module).
function Ctl:scratch(name)
  local d = self.data[name]
  if not d then d = {} self.data[name] = d end
  return d
end

-- Sets the hardness of the roles the walking states drive: legs, arms, head.
function Ctl:set_hardness(legs, arms, head)
  local h, r = self.h, self.roles
  for _, i in ipairs(r.legs) do h[i] = legs end
  for _, i in ipairs(r.arms) do h[i] = arms end
  for _, i in ipairs(r.head) do h[i] = head end
end

-- Balance feedback (Player/Motion/balance.lua) for the walk's next advance(): the feet's F/T
-- (self.ft) against the ZMP the walk planned for the tick just done, into the walk's COM shift.
function Ctl:balance_update()
  self.walk:update_com_shift(self.sensors, self.dt)
end

-- Head angles requested by behavior (motion.head_command) into q: pan, tilt.
function Ctl:head_angles(q)
  local hd = self.roles.head
  for k = 1, #hd do q[hd[k]] = self.head[k] end
end

-- A request by name (see Lib/Motion.lua); unknown names are ignored (returns false). 'pattern'
-- takes args.file, a trajectory file for this body (Lib/trajectory.lua): read here, a bad one is
-- refused (returns false and the error naming the file and line) and the wish stays as it was.
function Ctl:request(name, args)
  if Motion.REQUESTS[name] == nil then return false end
  if name == 'pattern' then
    local file = type(args) == 'table' and args.file
    if type(file) ~= 'string' or file == '' then return false, "request 'pattern': no trajectory file given" end
    local ok, tr = pcall(trajectory.load, file, self.robot)
    if not ok then return false, tostring(tr) end
    self.pattern = tr
  end
  self.want = name
  if name == 'relax' then self.machine:event('relax', self) end
  return true
end

-- True when the IMU says the robot is falling or lying. The torso's pitch is compared with
-- bodyTilt plus `tilt`: 0, or while kicking the pitch the support leg's joints give with its foot
-- flat (the kick throws the torso back on purpose).
function Ctl:fall_detected()
  local p = self.p
  local roll, pitch = self.angle[1], self.angle[2] - p.bodyTilt - self.tilt
  local gx, gy = self.gyro[1], self.gyro[2]
  if abs(roll) > p.fallAngle or abs(pitch) > p.fallAngle then return true end
  -- tilted and still tilting further fast
  if abs(roll) > p.fallAngleRate and roll * gx > 0 and abs(gx) > p.fallRate then return true end
  if abs(pitch) > p.fallAngleRate and pitch * gy > 0 and abs(gy) > p.fallRate then return true end
  return false
end

-- One tick at robot time t: sensors must be filled in (self.pos, self.gyro, self.angle, self.acc).
-- Leaves the commands in self.q and hardness in self.h, and in self.write the joints to write.
function Ctl:tick(t)
  local dt = t - self.t
  if dt <= 0 or dt > 0.1 then dt = self.robot.period end
  self.t, self.dt = t, dt
  local n, q, h, hq, hh = self.n, self.q, self.h, self.hold_q, self.hold_h
  for i = 1, n do hq[i], hh[i] = q[i], h[i] end
  local m = self.machine
  if m.current ~= nil and WATCH_FALL[m.current] and self:fall_detected() then
    self.falls = self.falls + 1
    self.fall_time = t
    m:event('fall', self)
  end
  m:update(self)
  self.walk_kick:expire(t, m.current == 'walk' and self.walk:is_active())
  -- only the current state's joints keep what was written; a taken joint gets the caller's command
  local owned, taken, write, owner, touch = self.owned, self.taken, self.write, self.owner, self.touch
  for i = 1, n do
    if taken[i] then
      q[i], h[i], write[i], owner[i] = self.taken_q[i], hh[i], true, 2
    elseif owned[i] then
      write[i], owner[i] = true, 1
    else
      q[i], h[i], write[i], owner[i] = hq[i], hh[i], touch[i] or false, 0
    end
    touch[i] = nil
  end
end

function Ctl:state() return self.machine:state() end
function Ctl:state_index() return self.machine:index() end
function Ctl:since() return self.machine:since(self.t) end

return M
