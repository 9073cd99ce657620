-- The `wbc` shm block between Lib/WBC.lua (the REPL, behavior) and the motion state wbc
-- (Player/Motion/states/wbc.lua): before a tick a new target request goes into ctl.wbc_inbox (or is
-- refused at once when the state is not running) and a new skill request into ctl.wbc_skill (the
-- state takes it when it runs or starts); after it, what the state did with the requests and its
-- tasks' status are written back. The block is written only while the state runs (and once when it
-- stops, or to answer a request); a tick makes no garbage (the writer is made once, the names are
-- written when the task list grows).
local ffi = require('ffi')

local M = {}
local Link = {}
Link.__index = Link

local NAME = 32   -- bytes per task name (Config/shm.schema: nwbc_names / nwbc)
local NTASK = 16  -- tasks reported (Config/shm.schema: nwbc)
-- a task kind's number in the block (Modules/wbc/wbc.h's enum, as Lib/wbc.lua's KINDS)
M.KIND = { position = 0, orientation = 1, pose = 2, com = 3, com_xy = 4, posture = 5 }

local function put_string(dst, len, s)
  ffi.fill(dst, len)
  ffi.copy(dst, s, math.min(#s, len - 1))
end

-- The status into block x (inside its write lock): self.done, self.skill_done, self.r, self.tick.
local function write_status(self, x)
  local done, sdone, r = self.done, self.skill_done, self.r
  if done then
    x.done_rc[0] = done.ok and 0 or -1
    put_string(x.done_error, 256, done.error or '')
    x.done_seq[0] = done.seq
  end
  if sdone then
    x.skill_rc[0] = sdone.ok and 0 or -1
    put_string(x.skill_error, 256, sdone.error or '')
    x.skill_done[0] = sdone.seq
  end
  x.tick[0] = self.tick
  x.active[0] = r and 1 or 0
  if not r then return end
  x.feasible[0] = r.feasible and 1 or 0
  x.step_us[0] = r.step_us
  if r.skill ~= self.skill then
    put_string(x.skill, NAME, r.skill)
    self.skill = r.skill
  end
  if r.skill_state ~= self.skill_state then
    put_string(x.skill_state, NAME, r.skill_state)
    self.skill_state = r.skill_state
  end
  x.skill_time[0] = r.skill_time
  local n = math.min(#r.tasks, NTASK)
  if n ~= self.named then
    for i = 1, n do put_string(x.task_name + (i - 1) * NAME, NAME, r.tasks[i].name) end
    self.named = n
  end
  x.ntask[0] = n
  for i = 1, n do
    local s = r.tasks[i]
    x.task_level[i - 1] = s.level
    x.task_enabled[i - 1] = s.enabled and 1 or 0
    x.task_feasible[i - 1] = s.feasible and 1 or 0
    x.task_error[i - 1] = s.error
    x.task_sigma[i - 1] = s.sigma_min
    x.task_held[i - 1] = s.held and 1 or 0
    x.task_kind[i - 1] = M.KIND[s.kind] or -1
  end
end

function M.new(block)
  local self = setmetatable({ b = block, last = block.request_seq[0], skill_seq = nil, active = false }, Link)
  self.writer = function(x) write_status(self, x) end
  return self
end

local function read_request(x)
  local n = x.request_n[0]
  local target
  if n > 0 then
    target = {}
    for i = 1, math.min(n, 32) do target[i] = x.request_target[i - 1] end
  end
  return { seq = x.request_seq[0], task = ffi.string(x.request_task), target = target }
end

local function read_skill(x) return ffi.string(x.request_skill) end

-- A new request: into ctl.wbc_inbox for the state, or refused when the state is not running. The
-- skill asked for (at the first tick too: a restarted process keeps the block's) into ctl.wbc_skill
-- (nil: the default) and ctl.wbc_skill_seq.
function Link:before(ctl)
  local b = self.b
  local sseq = b.skill_seq[0]
  if sseq ~= self.skill_seq then
    self.skill_seq = sseq
    local name = b:read(read_skill)
    ctl.wbc_skill, ctl.wbc_skill_seq = name ~= '' and name or nil, sseq
  end
  local seq = b.request_seq[0]
  if seq == self.last then return end
  self.last = seq
  local req = b:read(read_request)
  if ctl:state() == 'wbc' then
    ctl.wbc_inbox = req
  else
    ctl.wbc_done = { seq = req.seq, ok = false,
      error = "the wbc motion is not running (Motion.request('wbc')): target of '" .. req.task .. "' dropped" }
  end
end

-- The answers to the last requests and the tasks' status (ctl.wbc_report, nil: the state is not
-- running); nothing is written while the state does not run and there is nothing to answer.
function Link:after(ctl, tick)
  local done, sdone, r = ctl.wbc_done, ctl.wbc_skill_done, ctl.wbc_report
  if not (r or done or sdone or self.active) then return end
  ctl.wbc_done, ctl.wbc_skill_done = nil, nil
  self.done, self.skill_done, self.r, self.tick = done, sdone, r, tick
  self.b:write(self.writer)
  self.active = r ~= nil
end

return M
