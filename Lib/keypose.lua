-- Key-pose playback by a caller (a REPL script, an operator's tool): a keyframe file of the body
-- (Config/robots/<ROBOT>/keyframes/<name>.lua, the format of Player/Motion/keyframe.lua: frames of
-- joint angles by name and durations, interpolated smoothly) played through Body commands. Each
-- joint the file names is taken from the motion process for the playback (Body.set_command: the
-- stance or the walk goes on with the other joints, a joint no state drives, such as a waist, is
-- simply commanded) and given back at the end (Body.release). The frames' hardness is left to the
-- motion process. This is how the DRC-HUBO operators moved the robot: interpolating key poses.
--
--   local keypose = require('keypose')
--   keypose.play('wave', wait)     -- blocks until done; wait(s) advances the robot's clock (REPL)
--   local kf = keypose.load('wave') -- the checked motion: joints, frames, duration
local Body = require('Body')
local Config = require('Config')
local kin = require('kinematics')
local control = require('Motion.control')
local keyframe = require('Motion.keyframe')

local M = {}

-- The checked keyframe motion `name` of this body (errors name the file, the frame and the joint).
function M.load(name)
  local robot = Config.load('robot')
  local body = control.keyframe_body(robot, kin.load())
  local kf = keyframe.load(name, body, robot.name)
  return kf, keyframe.duration(kf)
end

-- Plays key-pose motion `name` from the present commands: every tick (Body.period()) the joints it
-- names are commanded, `wait` advancing the clock; then the joints are released. Returns the
-- largest difference between a joint's commanded and measured angle seen over the playback (rad).
function M.play(name, wait)
  if type(wait) ~= 'function' then error('keypose.play: wait(seconds) expected', 2) end
  local kf = M.load(name)
  local names = Body.joint_names()
  local q0, q, h = Body.get_commands(), {}, {}
  local dt = Body.period()
  local player = keyframe.play(kf, Body.get_time(), q0, 1)
  local worst = 0
  repeat
    local done = player:update(Body.get_time(), q, h)
    for _, j in ipairs(kf.joints) do
      Body.set_command(names[j], q[j])
      worst = math.max(worst, math.abs(Body.get_position(names[j]) - Body.get_command(names[j])))
    end
    wait(dt)
  until done
  for _, j in ipairs(kf.joints) do Body.release(names[j]) end
  return worst
end

return M
