-- walk: the ZMP walk at the commanded velocity; stops into stance when something else is asked.
local M = {}

function M.entry(c)
  c.walk:start()
end

function M.update(c)
  local w, v = c.walk, c.vel_cmd
  w:set_velocity(v[1], v[2], v[3])
  if c.want ~= 'walk' then w:stop() end
  local active = w:advance(c.dt)
  w:joint_angles(c.q, c.sensors, c.dt)
  c:head_angles(c.q)
  w:update_com_offset(c.q)
  c:set_hardness(c.p.hardnessLegs, c.p.hardnessArms, c.p.hardnessHead)
  if not active then return 'done' end
end

return M
