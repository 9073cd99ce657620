-- What the behavior asks of the body: walk velocity, stand, kick, head angles. Goes through the
-- motion process's API (Lib/Motion.lua: Motion.request/state; Lib/Walk.lua: Walk.set_velocity);
-- head angles through the motion block's head_command (the motion process moves the head).
local shm = require('shm')

local M = {}

local motion = shm.open('motion')

local Motion, Walk
do
  local ok, mod = pcall(require, 'Motion')
  if ok and type(mod) == 'table' then Motion = mod end
  ok, mod = pcall(require, 'Walk')
  if ok and type(mod) == 'table' then Walk = mod end
end
M.available = Motion ~= nil and Walk ~= nil

-- Motion states during which the behavior must not ask for walking (it would cut them short).
local BUSY = { kick_left = true, kick_right = true, kick = true, falling = true, fallen = true,
  standup = true, standup_front = true, standup_back = true, stand_up = true, getup = true }

local last = { vx = 0, vy = 0, va = 0 }
M.last = last
M.kicks = 0
-- the motion process (pid) our last request went to: a restarted motion process starts from its
-- initial state and ignores what the block asked of its predecessor, so we ask it again
M.asked_pid = nil

local function ask(name)
  Motion.request(name)
  M.asked_pid = motion.pid[0]
end

-- Whether the motion process running now has heard our wish for `state` (a request name's state).
local function asked(state)
  return Motion.requested() == state and M.asked_pid == motion.pid[0]
end

function M.motion_state()
  if Motion and Motion.state then
    local ok, s = pcall(Motion.state)
    if ok then return s end
  end
  return nil
end

function M.busy()
  local s = M.motion_state()
  if s == nil then return false end
  return BUSY[s] or s:find('kick') ~= nil or s:find('stand_?up') ~= nil or s:find('fall') ~= nil
end

-- Whether the robot is down: falling, lying or getting up (its teammates are told: Team/roles.lua).
function M.down()
  local s = M.motion_state()
  return s ~= nil and (s:find('fall') ~= nil or s:find('stand_?up') ~= nil)
end

local function set_velocity(vx, vy, va)
  last.vx, last.vy, last.va = vx, vy, va
  if Walk then Walk.set_velocity(vx, vy, va)
  else motion:set('velocity', { vx, vy, va }) end
end

-- Walk with (vx, vy, va); starts the walk when the robot stands.
function M.walk(vx, vy, va)
  set_velocity(vx, vy, va)
  if Motion and not M.busy() and M.motion_state() ~= 'walk' and not asked('walk') then
    ask('walk')
  end
end

-- Stop walking and stand.
function M.stop()
  set_velocity(0, 0, 0)
  if Motion and not M.busy() then
    local s = M.motion_state()
    if s ~= 'stance' and not asked('stance') then ask('stand') end
  end
end

-- Kick with the left or right foot; false when the motion process cannot kick now.
function M.kick(side)
  if not Motion or M.busy() then return false end
  set_velocity(0, 0, 0)
  ask(side == 'left' and 'kick_left' or 'kick_right')
  M.kicks = M.kicks + 1
  return true
end

-- A kick out of the walk ('forward' or 'side') with the left or right foot through the ball at
-- (bx, by) m, robot frame: the walk goes on. False when the robot is not walking.
function M.walk_kick(kind, foot, bx, by)
  if not (Walk and Walk.kick) or M.motion_state() ~= 'walk' then return false end
  Walk.kick(kind, foot, bx, by)
  M.kicks = M.kicks + 1
  return true
end

-- The walk's current (rate-limited) velocity: vx, vy (m/s), va (rad/s).
function M.walk_velocity()
  if not (Walk and Walk.velocity) then return last.vx, last.vy, last.va end
  return Walk.velocity()
end

-- The kicks out of the walk the motion process has made (a counter).
function M.walk_kicks()
  if not (Walk and Walk.kick_status) then return 0 end
  local _, n = Walk.kick_status()
  return n
end

-- Drops a kick out of the walk still waiting for its step.
function M.walk_kick_cancel()
  if Walk and Walk.kick then Walk.kick(nil) end
end

-- The kick out of the walk: 'none', 'asked' (waiting for its step) or 'kicking'.
function M.walk_kick_phase()
  if not (Walk and Walk.kick_status) then return 'none' end
  return (Walk.kick_status())
end

-- Head angles (rad): pan, tilt in the joint convention of Config/<platform>/robot.lua.
function M.head(pan, tilt)
  motion.head_command[0], motion.head_command[1] = pan, tilt
end

return M
