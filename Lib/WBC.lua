-- Whole-body control from the REPL and behavior: targets for the motion state `wbc`
-- (Player/Motion/states/wbc.lua, docs/whole-body.md) and its tasks' status, through the `wbc` block.
--
--   Motion.request('wbc')
--   WBC.set_target('r_palm', { 0.35, -0.25, 0.90 })  -- any frame of the body's URDF, or a task of the
--                                                     -- skill ('com': { x, y }); stance frame, metres
--   WBC.set_target('r_palm', nil)                     -- drop the task's target
--   p(WBC.status())  --> { active = true, feasible = true, tick_us = 310,
--                    --     tasks = { r_palm = { level = 2, error = 0.004, feasible = true, enabled = true,
--                    --               sigma_min = 0.18, held = false }, com = {...} }, last = { seq, ok, error } }
--                    (held: out of reach for the skill's hold_after s, the target became where it got to)
--   WBC.skill('hello_bye')   -- the skill the state runs (Lib/wbc_skill.lua; nil: the default), from its
--                            -- first state: at once when the state runs, else when it starts
--   p(WBC.status().skill)    --> { name = 'hello_bye', state = 'wave_out', time = 0.8, last = { seq, ok, error } }
--
-- set_target checks what it can at once (a name, finite numbers, a frame the body has) and raises
-- an error naming it; the motion state applies the target on its next tick and answers in
-- status().last (refused: why, e.g. the state is not running). It does not wait: lockstep scripts
-- step the clock themselves.
local ffi = require('ffi')
local shm = require('shm')

local M = {}

local block = shm.lazy('wbc')
local model    -- the body's rigid-body model (Lib/dynamics.lua), loaded at the first target

local function finite(x) return type(x) == 'number' and x == x and x ~= math.huge and x ~= -math.huge end

local function known_frame(name)
  model = model or require('dynamics').load()
  model:set({})
  return (pcall(model.pose, model, name))
end

-- Posts a target (nil: none) for task or frame `name`; returns the request's sequence number.
function M.set_target(name, target)
  if type(name) ~= 'string' or #name == 0 or #name > 31 then
    error('WBC.set_target: the task or frame must be a name of 1..31 characters', 2)
  end
  if target ~= nil then
    if type(target) ~= 'table' or #target < 1 or #target > 32 then
      error(string.format("WBC.set_target('%s'): the target must be a list of 1..32 numbers", name), 2)
    end
    for i = 1, #target do
      if not finite(target[i]) then
        error(string.format("WBC.set_target('%s'): target[%d] is not a finite number (%s)", name, i,
          tostring(target[i])), 2)
      end
    end
    if name ~= 'com' and name ~= 'posture' and not known_frame(name) then
      local ok = pcall(require('Config').load, 'wbc')
      local skill = ok and require('Config').load('wbc').tasks or {}
      if rawget(skill, name) == nil and M.status().tasks[name] == nil then
        error(string.format("WBC.set_target: '%s' is neither a frame of the body nor a task of the skill", name), 2)
      end
    end
  end
  local seq
  block():write(function(x)
    ffi.fill(x.request_task, 32)
    ffi.copy(x.request_task, name)
    x.request_n[0] = target and #target or 0
    for i = 1, target and #target or 0 do x.request_target[i - 1] = target[i] end
    seq = x.request_seq[0] + 1
    x.request_seq[0] = seq
  end)
  return seq
end

-- Asks for skill `name` (nil or 'default': the wbc config's tasks alone); checks the skill's files
-- against the body at once (an error naming the file and the key). Returns the request's number.
function M.skill(name)
  if name ~= nil and type(name) ~= 'string' then error('WBC.skill: a skill name or nil expected', 2) end
  local skills = require('wbc_skill')
  if name == skills.DEFAULT then name = nil end
  if name ~= nil then
    local ok, err = pcall(skills.load, name, { has_frame = known_frame })
    if not ok then error('WBC.skill: ' .. tostring(err), 2) end
  end
  local seq
  block():write(function(x)
    ffi.fill(x.request_skill, 32)
    ffi.copy(x.request_skill, name or '')
    seq = x.skill_seq[0] + 1
    x.skill_seq[0] = seq
  end)
  return seq
end

-- The controller's state: see the header.
function M.status()
  return block():read(function(x)
    local s = { active = x.active[0] == 1, feasible = x.feasible[0] == 1, tick_us = x.step_us[0], tick = x.tick[0],
      tasks = {}, last = { seq = x.done_seq[0], ok = x.done_rc[0] == 0, error = ffi.string(x.done_error) } }
    if s.last.error == '' then s.last.error = nil end
    s.skill = { name = ffi.string(x.skill), state = ffi.string(x.skill_state), time = x.skill_time[0],
      last = { seq = x.skill_done[0], ok = x.skill_rc[0] == 0, error = ffi.string(x.skill_error) } }
    if s.skill.last.error == '' then s.skill.last.error = nil end
    if not s.active then return s end
    for i = 0, math.min(x.ntask[0], 16) - 1 do
      local name = ffi.string(x.task_name + i * 32)
      s.tasks[name] = { level = x.task_level[i], enabled = x.task_enabled[i] == 1, feasible = x.task_feasible[i] == 1,
        error = x.task_error[i], sigma_min = x.task_sigma[i], held = x.task_held[i] == 1 }
    end
    return s
  end)
end

return M
