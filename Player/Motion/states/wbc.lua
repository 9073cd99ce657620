-- wbc: whole-body control in kinematic mode (Modules/wbc through Lib/wbc.lua). The skill of the
-- wbc config (Config/common/wbc.lua, a body's own wbc.lua over it): its tasks in their levels under
-- the soles held on the ground; targets from Lib/WBC.lua (the REPL, behavior) arrive in c.wbc_inbox
-- (Player/Motion/wbc_link.lua), the tasks' status leaves in c.wbc_report. A target for a contact
-- (a sole) lifts it: it leaves the contacts and becomes a pose task (that position, its present
-- orientation); a nil target puts it down again as a contact where it is. Every joint is the
-- controller's; the angles it integrates are commanded each tick. A frame's task infeasible for
-- `hold_after` s (out of reach, singular) is held where the frame got to (status: held) instead of
-- leaning the body after it. Leaves through stance when another motion is asked for. A skill
-- (Lib/wbc_skill.lua: states of tasks and the rules between them) runs over the config's tasks: the
-- one c.wbc_skill names (WBC.skill, Motion.request('wbc', { skill = ... })), else the default.
-- A tick makes no garbage: the task list and the status tables are kept from tick to tick.
local Config = require('Config')
local wbc = require('wbc')
local wbc_skill = require('wbc_skill')
local wbc_torque = require('Motion.wbc_torque')   -- the skill's torque mode (a limb torque driven)

local M = {}

M.owns = { 'all' }

-- The controller and the skill, built once per process (a bad skill stops the state naming it).
local function skill(c)
  local d = c:scratch('wbc')
  if not d.ctl then
    local cfg = Config.load('wbc', nil, { robot = c.robot.name })
    local ctl = wbc.load({ robot = c.robot.name, dt = c.robot.period })
    for name, t in pairs(cfg.tasks) do ctl:add(name, t.kind, t) end
    ctl:max_lean(cfg.max_lean)
    local joint = {}
    for i, j in ipairs(c.robot.joints) do joint[j] = i end
    d.cfg, d.ctl, d.out, d.joint, d.entry_q = cfg, ctl, {}, joint, {}
    d.report = { tasks = {}, by_name = {}, skill = wbc_skill.DEFAULT, skill_state = '', skill_time = 0 }
    d.torque = wbc_torque.new(c, cfg)
  end
  return d
end

-- A task's target as numbers: 'stance' (com_xy: over the stance frame's origin), 'entry' (posture:
-- the pose the state started from), a posture's joints by name (the rest: the entry pose).
local function resolve(d, t)
  local target = t.target
  if target == 'stance' then return { 0, 0 } end
  if target == 'entry' then return d.entry_q end
  if t.kind == 'posture' and type(target) == 'table' and #target == 0 then
    local q = {}
    for i, a in ipairs(d.entry_q) do q[i] = a end
    for j, a in pairs(target) do q[d.joint[j]] = a end
    return q
  end
  return target
end

local function index_of(list, x)
  for i, v in ipairs(list) do if v == x then return i end end
end

-- A contact lifted to a position (its present orientation kept), or put down where it is (nil).
local function move_contact(d, name, target)
  local ctl, r = d.ctl, d.cfg.reach
  local held = index_of(d.contacts, name)
  if target == nil then
    if not held then d.contacts[#d.contacts + 1] = name end
    if ctl:has(name) then ctl:target(name, nil) end
    ctl:contacts(d.contacts)
    return
  end
  if #target ~= 3 then
    error(string.format("wbc: '%s' is a contact: its target is a position { x, y, z }", name), 0)
  end
  if held and #d.contacts == 1 then
    error(string.format("wbc: '%s' is the last contact: nothing would hold the body", name), 0)
  end
  if not ctl:has(name) then
    ctl:add(name, 'pose', { frame = name, level = r.level, gain = r.gain, max_rate = r.max_rate })
  end
  local R = ctl:pose(name).R
  ctl:target(name, { target[1], target[2], target[3], R[1], R[2], R[3], R[4], R[5], R[6], R[7], R[8], R[9] })
  if held then
    table.remove(d.contacts, held)
    ctl:contacts(d.contacts)
  end
end

-- A target for a task; a frame of the body that is no task yet becomes a position task (cfg.reach).
local function set_target(d, name, target)
  local ctl = d.ctl
  if index_of(d.cfg.contacts, name) then return move_contact(d, name, target) end
  d.held[name] = nil
  d.infeasible[name] = 0
  if not ctl:has(name) then
    if target == nil then return end
    local r = d.cfg.reach
    ctl:add(name, 'position', { frame = name, level = r.level, gain = r.gain, max_rate = r.max_rate })
  end
  ctl:target(name, target)
end

-- The skill `name` (nil: the default) from its first state; a skill that cannot run (a bad file,
-- a task its controller has with another kind) is refused naming why, and the default runs.
local function start_skill(c, d, name)
  local ctl = d.ctl
  if d.run then d.run:leave() end
  local ok, err = pcall(function()
    local s = wbc_skill.load(name, { robot = c.robot.name, base = d.cfg.tasks,
      has_frame = function(f) return ctl:has_frame(f) end })
    d.run = wbc_skill.run(s, ctl, d.cfg.tasks, function(_, t) return resolve(d, t) end)
  end)
  if not ok then
    d.run = wbc_skill.run(wbc_skill.load(nil), ctl, d.cfg.tasks, function(_, t) return resolve(d, t) end)
  end
  for _, tname in ipairs(d.run:enter(d.run.skill.initial)) do d.held[tname], d.infeasible[tname] = nil, 0 end
  d.report.skill = d.run.skill.name
  return ok, not ok and tostring(err) or nil
end

function M.entry(c)
  local d = skill(c)
  local ctl = d.ctl
  d.contacts, d.held, d.infeasible = {}, {}, {}
  for i, f in ipairs(d.cfg.contacts) do d.contacts[i] = f end
  ctl:contacts(d.contacts)
  ctl:reset(c.q)
  for i = 1, c.n do d.entry_q[i] = c.q[i] end
  -- the config's tasks as it says (a skill's state may have changed their levels and gains), the rest
  -- resting until a skill or a target names them
  for _, name in ipairs(ctl:tasks()) do
    local t = Config.optional(d.cfg.tasks, name)
    if t then
      ctl:level(name, t.level)
      ctl:gain(name, t.gain)
    end
    ctl:target(name, t and resolve(d, t) or nil)
  end
  d.report.tasks, d.report.by_name = {}, {}
  d.skill_seq, d.run = c.wbc_skill_seq, nil
  local ok, err = start_skill(c, d, c.wbc_skill)
  c.wbc_skill_done = { seq = c.wbc_skill_seq or 0, ok = ok, error = err }
  d.torque:entry()
end

local function apply_inbox(c, d)
  local inbox = c.wbc_inbox
  if not inbox then return end
  c.wbc_inbox = nil
  local ok, err
  if d.torque:owns(inbox.task) then
    ok, err = pcall(d.torque.set_target, d.torque, inbox.task, inbox.target)
  else
    ok, err = pcall(set_target, d, inbox.task, inbox.target)
  end
  c.wbc_done = { seq = inbox.seq, ok = ok, error = not ok and tostring(err) or nil }
end

local FRAME_KINDS = { position = true, pose = true, orientation = true }

-- A frame's task infeasible for hold_after s: its target becomes where the frame is.
local function hold_if_stuck(c, d, name, s)
  if not (s.enabled and FRAME_KINDS[s.kind]) or s.feasible then
    d.infeasible[name] = 0
    return
  end
  d.infeasible[name] = (d.infeasible[name] or 0) + c.dt
  if d.infeasible[name] < d.cfg.hold_after or d.held[name] then return end
  local p = d.ctl:pose(s.frame)
  if s.kind == 'position' then
    d.ctl:target(name, { p.x, p.y, p.z })
  elseif s.kind == 'pose' then
    local R = p.R
    d.ctl:target(name, { p.x, p.y, p.z, R[1], R[2], R[3], R[4], R[5], R[6], R[7], R[8], R[9] })
  else
    d.ctl:target(name, p.R)
  end
  d.held[name] = true
end

local function report(c, d)
  local ctl, r = d.ctl, d.report
  r.feasible = true
  for i, name in ipairs(ctl:tasks()) do
    local s = ctl:status(name, r.tasks[i])
    s.name = name
    r.tasks[i], r.by_name[name] = s, s
    hold_if_stuck(c, d, name, s)
    s.held = d.held[name] or false
    -- a posture fills whatever freedom is left: never met whole, it is not a task to flag
    if s.enabled and not s.feasible and s.kind ~= 'posture' then r.feasible = false end
  end
  r.step_us = ctl:step_us()
  return r
end

function M.update(c)
  local d = c:scratch('wbc')
  if c.wbc_skill_seq ~= d.skill_seq then   -- another skill asked for: it starts over
    d.skill_seq = c.wbc_skill_seq
    local ok, err = start_skill(c, d, c.wbc_skill)
    c.wbc_skill_done = { seq = c.wbc_skill_seq, ok = ok, error = err }
  end
  apply_inbox(c, d)
  local q = d.ctl:step(d.out)
  local h = d.cfg.hardness
  for _, i in ipairs(c.own) do c.q[i], c.h[i] = q[i], h end
  d.torque:update(c, d.ctl)
  local r = report(c, d)
  local run = d.run
  if run:update(c.dt, r.by_name) then
    for _, tname in ipairs(run.skill.states[run.state].names) do d.held[tname], d.infeasible[tname] = nil, 0 end
  end
  r.skill_state, r.skill_time = run.state, run.time
  d.torque:report(r, #d.ctl:tasks())
  c.wbc_report = r
  if c.want ~= 'wbc' then return 'done' end
end

function M.exit(c) c.wbc_report = nil end

return M
