-- Hang detection for the process manager (Run/main.lua): a process whose progress counter stands
-- still while its input moves on (a stopped, deadlocked or endlessly looping process) for `after`
-- seconds of robot time is reported, so that the manager stops it (SIGKILL works on a stopped
-- process too) and restarts it like one that died. Judged on the robot clock: under the lockstep a
-- stopped participant stops the clock, so nothing is judged hung there.
--
--   local hang = require('Run.hang')
--   local w = hang.new(2.0, { motion = { progress = fn, input = fn }, ... })
--   w:started('motion', robot_time)        -- a (re)start: a fresh process gets `startup` s first
--   local name, s = w:check(robot_time)    -- the first hung process and its stall (s), or nil
local M = {}
local Watch = {}
Watch.__index = Watch

-- after: s of robot time without progress while the input moves; startup: the same before the first
-- progress of a fresh process (loading config, the LUT, the kinematics takes a while).
function M.new(after, probes, startup)
  assert(type(after) == 'number' and after > 0, 'hang.new: after must be a positive number')
  local w = setmetatable({ after = after, startup = startup or math.max(10, after), procs = {} }, Watch)
  for name, p in pairs(probes) do
    assert(type(p.progress) == 'function' and type(p.input) == 'function',
      'hang.new: probe ' .. name .. ' needs progress() and input()')
    w.procs[name] = { probe = p }
  end
  return w
end

function Watch:started(name, now)
  local s = self.procs[name]
  if not s then return end
  s.progress, s.input, s.since, s.fresh = s.probe.progress(), s.probe.input(), now, true
end

function Watch:check(now)
  for name, s in pairs(self.procs) do
    if s.since then
      local p, i = s.probe.progress(), s.probe.input()
      if p ~= s.progress or now < s.since then
        -- progress (or a clock that went back: a new world): start counting again
        s.progress, s.input, s.since, s.fresh = p, i, now, s.fresh and p == s.progress
      elseif i ~= s.input and now - s.since > (s.fresh and self.startup or self.after) then
        local stalled = now - s.since
        s.since = nil   -- reported once; started() arms it again
        return name, stalled
      end
    end
  end
  return nil
end

return M
