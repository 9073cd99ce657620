-- relax: no torque; the commands follow the measured angles so that stiffening again is smooth.
local M = {}

-- every joint: relax lets the whole body go (a caller's hold on a joint too: see Lib/Body.lua)
M.owns = { 'all' }

function M.entry(c)
  for i = 1, c.n do c.h[i] = 0 end
end

function M.update(c)
  for i = 1, c.n do c.q[i] = c.pos[i] end
  if c.want ~= 'relax' then return c.want == 'sit' and 'sit' or 'stand' end
end

return M
