-- pattern: plays a joint trajectory file (Lib/trajectory.lua; ctl.pattern, read when it was asked
-- for: Motion.request('pattern', { file = ... })), then stance. Every joint of the body is the
-- file's: from the commands at entry to the file's first row in the pattern config's `blend` s
-- (smoothstep), then the rows at the file's times, linear between them, on the motion tick
-- (ctl.pattern_time: s into the file, negative while blending). Open loop: the planned angles are
-- what is commanded, as a pattern generated ahead is played on a robot; the walk's hardness.
local M = {}

M.owns = { 'all' }

local function config(c)
  c.pattern_cfg = c.pattern_cfg or require('Config').load('pattern')
  return c.pattern_cfg
end

function M.entry(c)
  local d = c:scratch('pattern')
  d.q0, d.qp = d.q0 or {}, d.qp or {}
  d.tr = c.pattern
  d.t0 = c.t
  d.blend = config(c).blend
  for i = 1, c.n do d.q0[i] = c.q[i] end
end

function M.update(c)
  local d = c:scratch('pattern')
  local tr = d.tr
  if not tr then
    c.want = 'stand'
    return 'done'
  end
  local s = c.t - d.t0
  local tau = s - d.blend
  local q0, qp, q = d.q0, d.qp, c.q
  if tau < 0 then
    tr:joints_at(0, qp)
    local u = d.blend > 0 and s / d.blend or 1
    local a = u * u * (3 - 2 * u)
    for i = 1, c.n do q[i] = q0[i] + a * (qp[i] - q0[i]) end
  else
    tr:joints_at(tau, q)
  end
  c.pattern_time = tau
  c:set_hardness(c.p.hardnessLegs, c.p.hardnessArms, c.p.hardnessHead)
  if tau >= tr.duration then
    -- played: back to stance
    if c.want == 'pattern' then c.want = 'stand' end
    return 'done'
  end
end

function M.exit(c)
  c.pattern_time = nil
  c.pattern = nil
end

return M
