-- A small state-machine library. A state is a module (one small file) with optional
-- entry(ctx), update(ctx) and exit(ctx); update returns an event name or nil. Transitions are
-- declared in one place per machine:
--
--   local fsm = require('fsm')
--   local body = fsm.new({
--     name = 'body',
--     states = { 'idle', 'search', 'approach' },      -- order gives each state's index (0-based)
--     load = function(name) return require('BodyFSM.' .. name) end,
--     initial = 'idle',
--     transitions = {
--       idle = { start = 'search' },
--       search = { ball = 'approach' },
--       approach = { lost = 'search' },
--       ['*'] = { stop = 'idle' },                     -- from any state (a state's own entry wins)
--     },
--   })
--   body:update(ctx)        -- enters the initial state on first call, runs update, follows events
--   body:event('stop', ctx) -- an event from outside (game state, button ...)
--   body:state(), body:index(), body:since(t)
--
-- A state keeps what it needs from entry to exit in the context it is given, not in its module
-- (two machines, or two robots in one process, would share a module's upvalues):
--
--   function M.entry(ctx) local d = fsm.fresh(ctx, 'BodyFSM.search') d.t0 = ctx.t end
--   function M.update(ctx) local d = fsm.data(ctx, 'BodyFSM.search') ... end
--
-- A transition runs exit of the old state, then entry of the new one. An event no transition
-- names is counted in machine.unhandled[event] and otherwise ignored. Mistakes in the declaration
-- (unknown state, missing module) fail at new() with the machine and state named.
local M = {}

local Machine = {}
Machine.__index = Machine

local function check_state(def, name, where)
  for _, s in ipairs(def.states) do if s == name then return end end
  error(string.format("fsm '%s': %s names unknown state '%s'", def.name or '?', where, tostring(name)), 3)
end

function M.new(def)
  if type(def) ~= 'table' or type(def.states) ~= 'table' or #def.states == 0 then
    error('fsm.new: need a table with a non-empty list `states`', 2)
  end
  if type(def.load) ~= 'function' then error("fsm '" .. tostring(def.name) .. "': need load(name)", 2) end
  local name = def.name or 'fsm'
  local index, modules = {}, {}
  for i, s in ipairs(def.states) do
    if index[s] then error(string.format("fsm '%s': state '%s' listed twice", name, s), 2) end
    index[s] = i - 1
    local ok, mod = pcall(def.load, s)
    if not ok or type(mod) ~= 'table' then
      error(string.format("fsm '%s': state '%s' did not load: %s", name, s, tostring(mod)), 2)
    end
    for _, fn in ipairs({ 'entry', 'update', 'exit' }) do
      if mod[fn] ~= nil and type(mod[fn]) ~= 'function' then
        error(string.format("fsm '%s': state '%s' field '%s' must be a function", name, s, fn), 2)
      end
    end
    modules[s] = mod
  end
  local initial = def.initial or def.states[1]
  check_state(def, initial, 'initial')
  local transitions = def.transitions or {}
  for from, events in pairs(transitions) do
    if from ~= '*' then check_state(def, from, 'a transition from') end
    if type(events) ~= 'table' then
      error(string.format("fsm '%s': transitions.%s must be a table of event = state", name, from), 2)
    end
    for ev, to in pairs(events) do
      check_state(def, to, "event '" .. tostring(ev) .. "' from '" .. from .. "'")
    end
  end
  return setmetatable({
    name = name, states = def.states, index_of = index, modules = modules, initial = initial,
    transitions = transitions, current = nil, t_entry = nil, unhandled = {}, history = {},
    on_transition = def.on_transition,
  }, Machine)
end

local function now_of(ctx)
  return ctx and ctx.t or 0
end

function Machine:_enter(s, ctx, ev)
  local from = self.current
  self.current = s
  self.t_entry = now_of(ctx)
  local h = self.history
  h[#h + 1] = s
  if #h > 32 then table.remove(h, 1) end
  if self.on_transition then self.on_transition(self, from, s, ev) end
  local mod = self.modules[s]
  if mod.entry then mod.entry(ctx) end
end

-- Follows `event` from the current state; true if a transition happened.
function Machine:event(ev, ctx)
  if ev == nil then return false end
  if not self.current then self:_enter(self.initial, ctx) end
  local from = self.current
  local to = (self.transitions[from] or {})[ev] or (self.transitions['*'] or {})[ev]
  if not to then
    self.unhandled[ev] = (self.unhandled[ev] or 0) + 1
    return false
  end
  local mod = self.modules[from]
  if mod.exit then mod.exit(ctx) end
  self:_enter(to, ctx, ev)
  return true
end

-- Runs the current state's update (entering the initial state first if needed) and follows the
-- event it returns. Returns the event (or nil).
function Machine:update(ctx)
  if not self.current then self:_enter(self.initial, ctx) end
  local mod = self.modules[self.current]
  local ev = mod.update and mod.update(ctx)
  if ev ~= nil then self:event(ev, ctx) end
  return ev
end

-- Forces the machine into state `s` (exit/entry run); for resets.
function Machine:set(s, ctx)
  if self.index_of[s] == nil then
    error("fsm '" .. self.name .. "': unknown state '" .. tostring(s) .. "'", 2)
  end
  if self.current then
    local mod = self.modules[self.current]
    if mod.exit then mod.exit(ctx) end
  end
  self:_enter(s, ctx, 'set')
end

-- The data of the activation of the state named `key` (by convention its module's name) that has
-- begun: a new table in ctx.fsm_data (call it from entry).
function M.fresh(ctx, key)
  local all = ctx.fsm_data
  if not all then all = {} ctx.fsm_data = all end
  local d = {}
  all[key] = d
  return d
end

-- The data of the current activation of the state named `key` (an empty table before its entry).
function M.data(ctx, key)
  local all = ctx.fsm_data
  local d = all and all[key]
  if not d then d = M.fresh(ctx, key) end
  return d
end

function Machine:state() return self.current or self.initial end
function Machine:index() return self.index_of[self.current or self.initial] end
-- Seconds spent in the current state at time t (the ctx.t given at entry).
function Machine:since(t) return t - (self.t_entry or t) end

return M
