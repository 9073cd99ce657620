-- The motion controller: one tick = read sensors, run the motion state machine, produce joint
-- commands and hardness. Independent of shm (Player/Motion/main.lua feeds it), so it can be
-- driven by tests and benchmarks directly.
--
-- States (Lib/Motion.lua's STATES, one small file each in Player/Motion/states/): relax, sit,
-- stance, walk, kick_left, kick_right, falling, standup_front, standup_back. Requests (relax,
-- sit, stand, walk, kick_left, kick_right) are wishes: `ctl.want` holds the last one and the
-- states move towards it (relax at once from anywhere; the rest through stance).
local fsm = require('fsm')
local Motion = require('Motion')
local Walk = require('Motion.walk')
local keyframe = require('Motion.keyframe')
local Kick = require('Motion.kick')

local abs = math.abs

local M = {}
local Ctl = {}
Ctl.__index = Ctl

local TRANSITIONS = {
  relax = { sit = 'sit', stand = 'stance', walk = 'stance', kick_left = 'stance', kick_right = 'stance' },
  sit = { stand = 'stance', walk = 'stance', kick_left = 'stance', kick_right = 'stance' },
  stance = { sit = 'sit', walk = 'walk', kick_left = 'kick_left', kick_right = 'kick_right', fall = 'falling' },
  walk = { done = 'stance', fall = 'falling' },
  kick_left = { done = 'stance', fall = 'falling' },
  kick_right = { done = 'stance', fall = 'falling' },
  falling = { front = 'standup_front', back = 'standup_back', stand = 'stance' },
  standup_front = { done = 'stance', fall = 'falling' },
  standup_back = { done = 'stance', fall = 'falling' },
  ['*'] = { relax = 'relax' },
}
-- states in which a fall is watched for (the stand-ups check the result themselves)
local WATCH_FALL = { stance = true, walk = true, kick_left = true, kick_right = true }

-- opts: robot (Config robot table), params (walk config, read live), model (kinematics),
-- initial (state name, default 'stance').
function M.new(opts)
  local robot, params = opts.robot, opts.params
  local n = #robot.joints
  local c = setmetatable({
    robot = robot, p = params, model = opts.model, n = n,
    q = {}, h = {}, pos = {}, gyro = { 0, 0, 0 }, angle = { 0, 0, 0 }, acc = { 0, 0, 9.81 },
    t = 0, dt = robot.period, want = 'stand', falls = 0, fall_time = -1, tilt = 0,
    vel_cmd = { 0, 0, 0 }, head = { 0, 0 },
  }, Ctl)
  for i = 1, n do c.q[i], c.h[i], c.pos[i] = 0, 0, 0 end
  c.sensors = { gyro = c.gyro, position = c.pos, angle = c.angle, acc = c.acc }
  c.walk = Walk.new(params, opts.model):bind(robot)
  c.kick = Kick.new(c.walk)
  c.ji = c.walk.ji
  -- hardness groups
  c.group = {}
  for gname, members in pairs(robot.groups) do
    local idx = {}
    for k, name in ipairs(members) do idx[k] = c.ji[name] end
    c.group[gname] = idx
  end
  -- keyframe motions are checked at start: a bad file stops the process with the file named
  c.keyframes = {}
  for _, name in ipairs({ 'sit', 'standup_front', 'standup_back' }) do
    c.keyframes[name] = keyframe.load(name, n, robot.name)
  end
  c.machine = fsm.new({
    name = 'motion',
    states = Motion.STATES,
    load = function(s) return require('Motion.states.' .. s) end,
    initial = opts.initial or 'stance',
    transitions = TRANSITIONS,
    on_transition = function(_, from) c.prev = from end,
  })
  return c
end

-- Sets the hardness of the standard groups: legs, arms, head.
function Ctl:set_hardness(legs, arms, head)
  local h, g = self.h, self.group
  for _, i in ipairs(g.lleg) do h[i] = legs end
  for _, i in ipairs(g.rleg) do h[i] = legs end
  for _, i in ipairs(g.larm) do h[i] = arms end
  for _, i in ipairs(g.rarm) do h[i] = arms end
  for _, i in ipairs(g.head) do h[i] = head end
end

-- Head angles requested by behavior (motion.head_command) into q.
function Ctl:head_angles(q)
  local ji = self.ji
  q[ji.head_pan], q[ji.head_tilt] = self.head[1], self.head[2]
end

-- A request by name (see Lib/Motion.lua); unknown names are ignored (returns false).
function Ctl:request(name)
  if Motion.REQUESTS[name] == nil then return false end
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
-- Leaves the commands in self.q and hardness in self.h.
function Ctl:tick(t)
  local dt = t - self.t
  if dt <= 0 or dt > 0.1 then dt = self.robot.period end
  self.t, self.dt = t, dt
  local m = self.machine
  if m.current == nil then m:update(self) return end
  if WATCH_FALL[m.current] and self:fall_detected() then
    self.falls = self.falls + 1
    self.fall_time = t
    m:event('fall', self)
  end
  m:update(self)
end

function Ctl:state() return self.machine:state() end
function Ctl:state_index() return self.machine:index() end
function Ctl:since() return self.machine:since(self.t) end

return M
