-- sit: the body's sit keyframes from the current pose, then hold.
local keyframe = require('Motion.keyframe')

local M = {}

-- the joints the body's keyframes/sit.lua names
function M.owns(c) return c.keyframes.sit.joints end

function M.entry(c)
  c:scratch('sit').player = keyframe.play(c.keyframes.sit, c.t, c.q, c.h)
end

function M.update(c)
  local player = c:scratch('sit').player
  player:update(c.t, c.q, c.h)
  if c.want ~= 'sit' and player.done then return 'stand' end
end

return M
