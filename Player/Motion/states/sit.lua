-- sit: the body's sit keyframes from the current pose, then hold.
local keyframe = require('Motion.keyframe')

local M = {}
local player

function M.entry(c)
  player = keyframe.play(c.keyframes.sit, c.t, c.q, c.h)
end

function M.update(c)
  player:update(c.t, c.q, c.h)
  if c.want ~= 'sit' and player.done then return 'stand' end
end

return M
