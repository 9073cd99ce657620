-- Whole-body skills (docs/whole-body.md, "Skills"): what the motion state wbc runs over the body's
-- base tasks (the wbc config's `tasks`: the balance, the posture). A skill is a set of states; each
-- state is a list of tasks (kind, frame, level, gain, max_rate, max_accel, target, as the base tasks) and
-- rules that move it on: to state `go` when the named tasks' errors are all under their bounds
-- (`reached`) or after `after` s in the state, a rule with `times` at most that often per run. The
-- default skill ('default') is the base tasks alone, in one state 'hold'.
--
-- A skill file: the concern wbc_skills/<name> (Config/common/wbc_skills/<name>.lua, a body's
-- Config/robots/<body>/wbc_skills/<name>.lua over it). Its shape is checked by
-- Config/spec/wbc_skills.lua on every load; its frames, joints and task names against the body and
-- the base tasks here. Every error names the file and the key.
--
--   local skills = require('wbc_skill')
--   local s = skills.load('hello_bye', { robot = 'hubo2plus', has_frame = function(f) ... end })
--   local run = skills.run(s, ctl, base_tasks, resolve)   -- resolve(name, task): its target's numbers
--   run:enter(s.initial)      -- targets, levels and gains of the state's tasks into the controller
--   run:update(dt, status)    -- status[name].error: a rule whose condition holds moves it on
--   run.state, run.time       -- the state's name, s in it
local Config = require('Config')

local M = {}

M.DEFAULT = 'default'
local FRAME_KINDS = { position = true, orientation = true, pose = true }

-- The concern of skill `name`.
function M.concern(name) return 'wbc_skills/' .. name end

local function fail(files, key, msg) error(string.format("%s: key '%s' %s", files, key, msg), 0) end

-- The default skill: the base tasks alone.
local function default_skill()
  return { name = M.DEFAULT, files = 'Config/common/wbc.lua', initial = 'hold',
    states = { hold = { name = 'hold', tasks = {}, names = {}, rules = {} } }, order = { 'hold' } }
end

local function sorted_keys(t)
  local keys = {}
  for k in pairs(t) do keys[#keys + 1] = k end
  table.sort(keys)
  return keys
end

-- Skill `name` for a body: opts.robot (default ROBOT), opts.has_frame(name) -> bool (the body's
-- frames: a model's or the controller's), opts.base (the wbc config's tasks; default: loaded).
-- Raises an error naming the file and the key (an unknown skill: the files looked for).
function M.load(name, opts)
  opts = opts or {}
  if name == nil or name == '' or name == M.DEFAULT then return default_skill() end
  if type(name) ~= 'string' or not name:match('^[%w_]+$') or #name > 31 then
    error(string.format("wbc skill: '%s' is not a skill name (letters, digits, _; up to 31)", tostring(name)), 0)
  end
  local copts = { robot = opts.robot }
  local concern = M.concern(name)
  -- the shape: Config/spec/wbc_skills.lua (the message without this line's position: it names the files)
  local loaded, cfg = pcall(Config.load, concern, nil, copts)
  if not loaded then error((tostring(cfg):gsub('^[^\n]-wbc_skill%.lua:%d+: ', '')), 0) end
  local function where(key) return Config.origin(concern, key, copts) end
  local robot = Config.load('robot', nil, copts)
  local base = opts.base or Config.load('wbc', nil, copts).tasks
  local joint = {}
  for _, j in ipairs(robot.joints) do joint[j] = true end
  local skill = { name = name, files = table.concat(Config.files(concern, copts), ' + '), initial = cfg.initial,
    states = {}, order = sorted_keys(cfg.states) }
  local declared = {}   -- task name -> { kind, frame, max_rate, key } first seen (base tasks first)
  for tname, t in pairs(base) do
    declared[tname] = { kind = t.kind, frame = rawget(t, 'frame') or tname, max_rate = t.max_rate, key = 'wbc.tasks' }
  end
  for _, sname in ipairs(skill.order) do
    local st = cfg.states[sname]
    local out = { name = sname, tasks = {}, names = sorted_keys(Config.optional(st, 'tasks', {})), rules = {} }
    for _, tname in ipairs(out.names) do
      local t = st.tasks[tname]
      local key = 'states.' .. sname .. '.tasks.' .. tname
      local frame = rawget(t, 'frame') or tname
      if FRAME_KINDS[t.kind] and opts.has_frame and not opts.has_frame(frame) then
        fail(where(key .. '.frame'), key .. '.frame', string.format("names '%s', which is no frame of the body %s",
          frame, robot.name))
      end
      local target = rawget(t, 'target')
      if t.kind == 'posture' and type(target) == 'table' and #target == 0 then
        for j in pairs(target) do
          if not joint[j] then
            fail(where(key .. '.target'), key .. '.target.' .. tostring(j),
              string.format("names no joint of the body %s", robot.name))
          end
        end
      elseif t.kind == 'posture' and type(target) == 'table' and #target ~= #robot.joints then
        fail(where(key .. '.target'), key .. '.target', string.format('must list %d joint angles (the body %s) or '
          .. 'map joint names to angles', #robot.joints, robot.name))
      end
      local d = declared[tname]
      if d and (d.kind ~= t.kind or d.frame ~= frame or d.max_rate ~= t.max_rate) then
        fail(where(key), key, string.format("must keep the kind, frame and max_rate of '%s' in %s (%s, %s, %s)",
          tname, d.key, d.kind, d.frame, tostring(d.max_rate)))
      end
      declared[tname] = d or { kind = t.kind, frame = frame, max_rate = t.max_rate, key = key }
      out.tasks[tname] = { kind = t.kind, frame = frame, level = t.level, gain = t.gain, max_rate = t.max_rate,
        max_accel = rawget(t, 'max_accel'), target = target }
    end
    local nexts = Config.optional(st, 'next', {})
    if rawget(nexts, 'go') then nexts = { nexts } end
    for i, rule in ipairs(nexts) do
      local key = 'states.' .. sname .. '.next' .. (rawget(st.next, 'go') and '' or '.' .. i)
      local reached = {}
      for tname, bound in pairs(Config.optional(rule, 'reached', {})) do
        if not out.tasks[tname] and rawget(base, tname) == nil then
          fail(where(key), key .. '.reached.' .. tostring(tname),
            string.format("names no task of state '%s' nor of the wbc config", sname))
        end
        reached[#reached + 1] = { task = tname, bound = bound }
      end
      table.sort(reached, function(a, b) return a.task < b.task end)
      out.rules[i] = { go = rule.go, reached = reached, after = Config.optional(rule, 'after'),
        times = Config.optional(rule, 'times') }
    end
    skill.states[sname] = out
  end
  return skill
end

local Run = {}
Run.__index = Run

-- A run of skill s on controller ctl over the base tasks (the wbc config's `tasks`); resolve(name,
-- task) gives a task's target as numbers (or nil), keywords resolved by the caller ('stance',
-- 'entry', a posture's joint map). Adds the skill's tasks the controller lacks (resting, no target).
function M.run(s, ctl, base, resolve)
  for _, sname in ipairs(s.order) do
    for _, tname in ipairs(s.states[sname].names) do
      local t = s.states[sname].tasks[tname]
      if not ctl:has(tname) then
        ctl:add(tname, t.kind, { frame = t.frame, level = t.level, gain = t.gain, max_rate = t.max_rate,
          max_accel = t.max_accel })
      end
    end
  end
  return setmetatable({ skill = s, ctl = ctl, base = base, resolve = resolve, state = nil, time = 0, fired = {},
    entered = {} }, Run)
end

-- The controller's task `name` as task t says (level, gain, target).
local function apply(self, name, t)
  local ctl = self.ctl
  ctl:level(name, t.level)
  ctl:gain(name, t.gain)
  ctl:target(name, self.resolve(name, t))
end

-- Enters state `name`: the tasks of the state left that this one lacks rest (a base task goes back
-- to the wbc config's level, gain and target); this state's tasks take theirs.
function Run:enter(name)
  local s = self.skill
  local to = s.states[name]
  self:leave(to)
  for _, tname in ipairs(to.names) do apply(self, tname, to.tasks[tname]) end
  self.state, self.time = name, 0
  self.entered[name] = (self.entered[name] or 0) + 1
  return to.names
end

-- Leaves the present state (for state `to`, or for none): its tasks that `to` lacks rest, a base
-- task back at the wbc config's level, gain and target.
function Run:leave(to)
  local from = self.state and self.skill.states[self.state]
  if not from then return end
  for _, tname in ipairs(from.names) do
    if not (to and to.tasks[tname]) then
      local b = rawget(self.base, tname)
      if b then apply(self, tname, b) else self.ctl:target(tname, nil) end
    end
  end
  self.state = nil
end

-- One tick of dt s after the controller's step; status[name] = { error = ... } of each task. A
-- rule that holds moves the skill to its state; returns that state's name (nil: it stays).
function Run:update(dt, status)
  self.time = self.time + dt
  local st = self.skill.states[self.state]
  for _, rule in ipairs(st.rules) do
    local left = not rule.times or (self.fired[rule] or 0) < rule.times
    if left then
      local ok = rule.after ~= nil and self.time >= rule.after
      if not ok and #rule.reached > 0 then
        ok = true
        for _, r in ipairs(rule.reached) do
          local ts = status[r.task]
          if not (ts and ts.enabled and ts.error <= r.bound) then ok = false break end
        end
      end
      if ok then
        self.fired[rule] = (self.fired[rule] or 0) + 1
        self:enter(rule.go)
        return rule.go
      end
    end
  end
end

M.Run = Run
return M
