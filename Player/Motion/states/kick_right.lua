-- kick_right: a kick with the right foot (Player/Motion/kick.lua), then stance.
local M = {}

function M.entry(c)
  c.kick:start('right', c.t)
  if c.want == 'kick_right' then c.want = 'stand' end
end

function M.update(c)
  local done = c.kick:update(c.t, c.q, c.sensors, c.dt)
  c:head_angles(c.q)
  c:set_hardness(c.p.hardnessLegs, c.p.hardnessArms, c.p.hardnessHead)
  if done then return 'done' end
end

return M
