-- The `wbc` shm block between Lib/WBC.lua (the REPL, behavior) and the motion state wbc
-- (Player/Motion/states/wbc.lua): before a tick a new target request goes into ctl.wbc_inbox (or is
-- refused at once when the state is not running); after it, what the state did with the request and
-- its tasks' status are written back.
local ffi = require('ffi')

local M = {}
local Link = {}
Link.__index = Link

local NAME = 32   -- bytes per task name (Config/shm.schema: nwbc_names / nwbc)

local function put_string(dst, len, s)
  ffi.fill(dst, len)
  ffi.copy(dst, s, math.min(#s, len - 1))
end

function M.new(block)
  return setmetatable({ b = block, last = block.request_seq[0] }, Link)
end

-- A new request: into ctl.wbc_inbox for the state, or refused when the state is not running.
function Link:before(ctl)
  local b = self.b
  local seq = b.request_seq[0]
  if seq == self.last then return end
  self.last = seq
  local req = b:read(function(x)
    local n = x.request_n[0]
    local target
    if n > 0 then
      target = {}
      for i = 1, math.min(n, 32) do target[i] = x.request_target[i - 1] end
    end
    return { seq = x.request_seq[0], task = ffi.string(x.request_task), target = target }
  end)
  if ctl:state() == 'wbc' then
    ctl.wbc_inbox = req
  else
    ctl.wbc_done = { seq = req.seq, ok = false,
      error = "the wbc motion is not running (Motion.request('wbc')): target of '" .. req.task .. "' dropped" }
  end
end

-- The answer to the last request and the tasks' status (ctl.wbc_report, nil: the state is not running).
function Link:after(ctl, tick)
  local done, r = ctl.wbc_done, ctl.wbc_report
  ctl.wbc_done = nil
  self.b:write(function(x)
    if done then
      x.done_rc[0] = done.ok and 0 or -1
      put_string(x.done_error, 256, done.error or '')
      x.done_seq[0] = done.seq
    end
    x.tick[0] = tick
    x.active[0] = r and 1 or 0
    if not r then return end
    x.feasible[0] = r.feasible and 1 or 0
    x.step_us[0] = r.step_us
    local n = math.min(#r.tasks, 16)
    x.ntask[0] = n
    for i = 1, n do
      local s = r.tasks[i]
      put_string(x.task_name + (i - 1) * NAME, NAME, s.name)
      x.task_level[i - 1] = s.level
      x.task_enabled[i - 1] = s.enabled and 1 or 0
      x.task_feasible[i - 1] = s.feasible and 1 or 0
      x.task_error[i - 1] = s.error
      x.task_sigma[i - 1] = s.sigma_min
      x.task_held[i - 1] = s.held and 1 or 0
    end
  end)
end

return M
