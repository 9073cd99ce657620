-- Shared by standup_front and standup_back: play the body's keyframe motion from the lying
-- pose; upright at the end -> stance, else fall again (and retry).
local keyframe = require('Motion.keyframe')

local M = {}

function M.make(name)
  local S = {}
  -- the joints the body's keyframes/<name>.lua names (none: a body without stand-ups, which
  -- never enters this state: falling.lua's fallPolicy)
  function S.owns(c)
    local kf = c.keyframes[name]
    return kf and kf.joints or {}
  end
  function S.entry(c)
    c:scratch(name).player = keyframe.play(c.keyframes[name], c.t, c.pos, c.h)
  end
  function S.update(c)
    local done = c:scratch(name).player:update(c.t, c.q, c.h)
    if not done then return nil end
    local roll, pitch = c.angle[1], c.angle[2] - c.p.bodyTilt
    if math.abs(roll) < c.p.fallAngleRate and math.abs(pitch) < c.p.fallAngleRate then return 'done' end
    c.falls = c.falls + 1
    return 'fall'
  end
  return S
end

return M
