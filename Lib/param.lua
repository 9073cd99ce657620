-- Every Config value live (Rhoban's RhIO, stanford-wbc's parameter reflection): read and set any key of
-- any concern while the robot's processes run, and save the changes into the config files.
--
--   param('walk.tStep')                -- the value in force (this process's Config plus the live changes)
--   param('walk.tStep', 0.30)          -- changes it in every running process that uses `walk`
--   param('vision.ball.max_range', 4)  -- nested keys by dots; list elements by number: 'vision.colors.1.y'
--   param.save() / param.save('walk.tStep')  -- writes the changed values into their config files
--   param.list('walk')  param.changes()  param.status()
--
-- How: the `param` shm block holds every change made since run_main started the processes (key,
-- type, value, a sequence number). Each process (motion, vision, behavior: param.follow) polls the
-- block's `seq` once per tick and writes new changes in place into the tables Config.load returned,
-- so every module that reads its config at run time sees them at once; a module that derives
-- something from a value at load registers a hook (follower:on('vision.scale', rebuild)). A
-- process started later (a restart) applies all changes held. Checked on both sides: an unknown key
-- is an error naming it and the files consulted; a value of another type than the config's, a NaN
-- or an infinity, a list of another length are refused.
local ffi = require('ffi')
local shm = require('shm')
local Config = require('Config')

ffi.cdef [[ int getpid(void); ]]

local M = {}

local KEY, NVAL, TEXT, NAME, CONCERNS = 64, 8, 64, 32, 64
local KINDS = { number = 1, boolean = 2, list = 3, string = 4 }
M.KINDS = KINDS

local block
local function param_block()
  block = block or shm.open('param')
  return block
end

-- 'walk.feedback.ankle' -> 'walk', { 'feedback', 'ankle' }; numbers index lists ('colors.1.y').
function M.split(key)
  if type(key) ~= 'string' or key == '' then error('param: key expected (e.g. "walk.tStep")', 3) end
  if #key >= KEY then error(string.format("param: key '%s' is longer than %d characters", key, KEY - 1), 3) end
  local parts = {}
  for part in key:gmatch('[^%.]+') do parts[#parts + 1] = tonumber(part) or part end
  if #parts == 0 or key:find('%.%.') or key:sub(1, 1) == '.' or key:sub(-1) == '.' then
    error(string.format("param: malformed key '%s'", key), 3)
  end
  local concern = table.remove(parts, 1)
  return tostring(concern), parts
end

-- The table holding path's last part, that part, and its value (nil when absent).
local function lookup(tbl, path)
  local parent = tbl
  for i = 1, #path - 1 do
    local v = rawget(parent, path[i])
    if type(v) ~= 'table' then return nil end
    parent = v
  end
  if #path == 0 then return nil, nil, tbl end
  return parent, path[#path], rawget(parent, path[#path])
end
M.lookup = lookup

local function finite(x) return type(x) == 'number' and x == x and x ~= math.huge and x ~= -math.huge end

local function is_number_list(t)
  if type(t) ~= 'table' or #t == 0 or #t > NVAL then return false end
  for k, v in pairs(t) do
    if type(k) ~= 'number' or type(v) ~= 'number' then return false end
  end
  return true
end

-- Checks a new value for key against the config table cfg (its files named in errors). Returns the
-- change { kind =, values = { ... } | text = } or nil and a message naming the key.
function M.check(cfg, key, path, value, files)
  local _, _, cur = lookup(cfg, path)
  if cur == nil then
    return nil, string.format("unknown key '%s'%s", key, files and (' (not in ' .. files .. ')') or '')
  end
  local t = type(cur)
  if t == 'number' then
    if type(value) ~= 'number' then return nil, string.format("'%s' is a number, got %s", key, type(value)) end
    if not finite(value) then return nil, string.format("'%s' must be a finite number, got %s", key, value) end
    return { kind = KINDS.number, values = { value } }
  elseif t == 'boolean' then
    if type(value) ~= 'boolean' then return nil, string.format("'%s' is a boolean, got %s", key, type(value)) end
    return { kind = KINDS.boolean, values = { value and 1 or 0 } }
  elseif t == 'string' then
    if type(value) ~= 'string' then return nil, string.format("'%s' is a string, got %s", key, type(value)) end
    if #value >= TEXT or value:find('%z') then
      return nil, string.format("'%s': a string of at most %d characters without NUL", key, TEXT - 1)
    end
    return { kind = KINDS.string, text = value }
  elseif is_number_list(cur) then
    if type(value) ~= 'table' or #value ~= #cur then
      return nil, string.format("'%s' is a list of %d numbers", key, #cur)
    end
    local values = {}
    for i = 1, #cur do
      if not finite(value[i]) then
        return nil, string.format("'%s': element %d must be a finite number, got %s", key, i, tostring(value[i]))
      end
      values[i] = value[i]
    end
    return { kind = KINDS.list, values = values }
  elseif t == 'table' then
    return nil, string.format("'%s' is a table: set its keys one by one ('%s.<key>')", key, key)
  end
  return nil, string.format("'%s' is a %s: not a parameter", key, t)
end

-- The Lua value of a change.
function M.value(change)
  if change.kind == KINDS.number then return change.values[1]
  elseif change.kind == KINDS.boolean then return change.values[1] ~= 0
  elseif change.kind == KINDS.string then return change.text end
  local t = {}
  for i, v in ipairs(change.values) do t[i] = v end
  return t
end

-- Writes a checked change into cfg in place (a list keeps its table: holders of it see the change).
-- Returns the previous value.
local function apply(cfg, path, change)
  local parent, k, cur = lookup(cfg, path)
  if change.kind == KINDS.list then
    local old = {}
    for i, v in ipairs(change.values) do old[i] = cur[i]; cur[i] = v end
    return old
  end
  rawset(parent, k, M.value(change))
  return cur
end

local function show(v)
  if type(v) == 'table' then
    local parts = {}
    for i, x in ipairs(v) do parts[i] = tostring(x) end
    return '{ ' .. table.concat(parts, ', ') .. ' }'
  end
  return type(v) == 'string' and string.format('%q', v) or tostring(v)
end
M.show = show

-- ---- the block: entries

local function cstr(ptr, len) return (ffi.string(ptr, len):gsub('%z.*$', '')) end
local function put(ptr, len, s)
  for i = 0, len - 1 do ptr[i] = i < #s and s:byte(i + 1) or 0 end
end

-- Reads entry i (0-based) of the block (inside a read).
local function entry(b, i)
  local e = { key = cstr(b.key + i * KEY, KEY), seq = b.entry_seq[i], kind = b.kind[i], saved = b.saved[i] ~= 0 }
  if e.kind == KINDS.string then e.text = cstr(b.text + i * TEXT, TEXT)
  else
    e.values = {}
    for k = 1, math.max(1, math.min(NVAL, b.nvalue[i])) do e.values[k] = b.value[i * NVAL + k - 1] end
  end
  return e
end

-- The changes with a sequence number after `since`, in the order they were made.
function M.entries(since)
  since = since or 0
  local b = param_block()
  local list = b:read(function(x)
    local out = {}
    for i = 0, math.min(x.entries[0], x:count('entry_seq')) - 1 do
      if x.entry_seq[i] > since then out[#out + 1] = entry(x, i) end
    end
    return out
  end)
  table.sort(list, function(a, c) return a.seq < c.seq end)
  return list
end

-- Every change held, { key, value, saved } in the order made.
function M.changes()
  local out = {}
  for _, e in ipairs(M.entries(0)) do out[#out + 1] = { key = e.key, value = M.value(e), saved = e.saved } end
  return out
end

-- Forgets every change (run_main does this when it starts the processes: a change not saved lasts
-- as long as that run). Follower slots of dead processes are freed.
function M.reset()
  local b = param_block()
  b:write(function(x)
    x.entries[0] = 0
    for i = 0, x:count('entry_seq') - 1 do x.entry_seq[i], x.saved[i] = 0, 0 end
    for i = 0, x:count('proc_pid') - 1 do
      if x.proc_pid[i] ~= 0 and shm.C.shm_pid_alive(x.proc_pid[i]) == 0 then x.proc_pid[i] = 0 end
    end
  end)
end

-- Records a checked change of key in the block (an earlier change of the same key is replaced).
local function publish(key, change)
  local b = param_block()
  local full = false
  b:write(function(x)
    local n, slot = x.entries[0], nil
    for i = 0, n - 1 do
      if cstr(x.key + i * KEY, KEY) == key then slot = i break end
    end
    if not slot then
      if n >= x:count('entry_seq') then full = true return end
      slot = n
      x.entries[0] = n + 1
      put(x.key + slot * KEY, KEY, key)
    end
    x.kind[slot] = change.kind
    if change.kind == KINDS.string then
      put(x.text + slot * TEXT, TEXT, change.text)
      x.nvalue[slot] = 0
    else
      x.nvalue[slot] = #change.values
      for k = 1, NVAL do x.value[slot * NVAL + k - 1] = change.values[k] or 0 end
    end
    x.saved[slot] = 0
    local seq = x.seq[0] + 1
    x.entry_seq[slot] = seq
    x.seq[0] = seq
  end)
  if full then
    error(string.format("param: %d keys changed already (the param block's nparam): param.save() and restart",
      b:count('entry_seq')), 3)
  end
end

-- Marks the changes of these keys saved.
local function mark_saved(keys)
  local b = param_block()
  b:write(function(x)
    for i = 0, x.entries[0] - 1 do
      if keys[cstr(x.key + i * KEY, KEY)] then x.saved[i] = 1 end
    end
  end)
end

-- ---- this process's view: Config plus the changes

local seen = 0 -- the last change applied to this process's Config

-- Applies the changes made since the last call to this process's Config (concerns it has not
-- loaded are loaded when asked for). Returns the list of { key, value, old } applied and the list of
-- refusals { key, message }.
local function catch_up(only_loaded)
  local b = param_block()
  if b.seq[0] == seen then return {}, {} end
  local loaded = {}
  for _, c in ipairs(Config.loaded()) do loaded[c] = true end
  local applied, refused = {}, {}
  for _, e in ipairs(M.entries(seen)) do
    local concern, path = M.split(e.key)
    if not only_loaded or loaded[concern] then
      local okc, cfg = pcall(Config.load, concern)
      local change, msg
      if okc then
        local v = M.value(e)
        change, msg = M.check(cfg, e.key, path, v)
      else
        msg = tostring(cfg)
      end
      if change then
        applied[#applied + 1] = { key = e.key, value = M.value(change), old = apply(cfg, path, change) }
      else
        refused[#refused + 1] = { key = e.key, message = msg }
      end
    end
    if e.seq > seen then seen = e.seq end
  end
  return applied, refused
end

-- The value of key in force here (after the live changes).
function M.get(key)
  local concern, path = M.split(key)
  catch_up(false)
  local ok, cfg = pcall(Config.load, concern)
  if not ok then error(string.format("param: unknown key '%s': %s", key, tostring(cfg)), 2) end
  local _, _, v = lookup(cfg, path)
  if v == nil then
    error(string.format("param: unknown key '%s' (not in %s)", key, table.concat(Config.files(concern), ' + ')), 2)
  end
  return v
end

-- Changes key to value in every process that follows the block (and here). Errors on an unknown key
-- or a refused value (the message names the key).
function M.set(key, value)
  local concern, path = M.split(key)
  catch_up(false)
  local ok, cfg = pcall(Config.load, concern)
  if not ok then error(string.format("param: unknown key '%s': %s", key, tostring(cfg)), 2) end
  local change, msg = M.check(cfg, key, path, value, table.concat(Config.files(concern), ' + '))
  if not change then error('param: ' .. msg, 2) end
  publish(key, change)
  return M.get(key)
end

-- Every leaf of a concern (or of a key's subtree) as sorted "key = value" pairs.
function M.list(prefix)
  local concern, path = M.split(prefix)
  catch_up(false)
  local _, _, t = lookup(Config.load(concern), path)
  if t == nil then error(string.format("param: unknown key '%s'", prefix), 2) end
  local out = {}
  local function walk(v, name)
    if type(v) == 'table' and not is_number_list(v) then
      for k, x in pairs(v) do walk(x, name .. '.' .. tostring(k)) end
    elseif type(v) ~= 'function' then
      out[#out + 1] = { key = name, value = v }
    end
  end
  walk(t, prefix)
  table.sort(out, function(a, c) return a.key < c.key end)
  return out
end

-- Writes the unsaved changes (or the change of one key) into their config files (Lib/param_save.lua:
-- the file of the highest layer that sets the key, edited in place). Returns { key = file }.
function M.save(key)
  local save = require('param_save')
  catch_up(false)
  local done, keys = {}, {}
  for _, e in ipairs(M.entries(0)) do
    if (key == nil and not e.saved) or e.key == key then
      local concern, path = M.split(e.key)
      local file = save.write(concern, path, M.value(e))
      done[e.key], keys[e.key] = file, true
    end
  end
  if key and not keys[key] then error(string.format("param.save: '%s' was not changed", key), 2) end
  mark_saved(keys)
  return done
end

-- The processes that follow the changes: { name, pid, alive, applied (all changes so far), concerns }.
function M.status()
  local b = param_block()
  local out = {}
  for i = 0, b:count('proc_pid') - 1 do
    local pid = b.proc_pid[i]
    if pid ~= 0 then
      out[#out + 1] = { name = cstr(b.proc_name + i * NAME, NAME), pid = pid,
        alive = shm.C.shm_pid_alive(pid) == 1, applied = b.proc_seq[i] == b.seq[0],
        refused = b.proc_refused[i], concerns = cstr(b.proc_concerns + i * CONCERNS, CONCERNS) }
    end
  end
  return out
end

-- ---- a robot process following the changes

local Follower = {}
Follower.__index = Follower

-- Claims a follower slot for this process (name: motion, vision, behavior) and applies the changes
-- held. Call follower:poll() once per tick. Without a free slot the process still follows, unlisted.
function M.follow(name, opts)
  local b = param_block()
  local pid = ffi.C.getpid()
  local self = setmetatable({ name = name, hooks = {}, quiet = opts and opts.quiet, slot = nil }, Follower)
  local pids = ffi.cast('volatile int32_t *', b.proc_pid)
  for i = 0, b:count('proc_pid') - 1 do
    local p = pids[i]
    if p == pid or p == 0 or shm.C.shm_pid_alive(p) == 0 then
      if shm.C.shm_cas_i32(pids + i, p, pid) == 1 then self.slot = i break end
    end
  end
  if self.slot then
    put(b.proc_name + self.slot * NAME, NAME, name)
    b.proc_seq[self.slot], b.proc_refused[self.slot] = 0, 0
  end
  self.last = -1
  self:poll()
  return self
end

-- fn(key, value, old) runs after a change of key or of a key below it (prefix 'vision.ball' sees
-- 'vision.ball.max_range'): for what a module derived from the config at load.
function Follower:on(prefix, fn)
  self.hooks[#self.hooks + 1] = { prefix = prefix, fn = fn }
  return self
end

local function under(key, prefix)
  return key == prefix or key:sub(1, #prefix + 1) == prefix .. '.'
end

-- Applies the changes made since the last poll (one compare when there are none).
function Follower:poll()
  local b = param_block()
  local seq = b.seq[0]
  if seq == self.last then return end
  self.last = seq
  local applied, refused = catch_up(true)
  for _, a in ipairs(applied) do
    if not self.quiet then
      io.stdout:write(string.format('[param] %s: %s = %s (was %s)\n', self.name, a.key, show(a.value), show(a.old)))
    end
    for _, h in ipairs(self.hooks) do
      if under(a.key, h.prefix) then h.fn(a.key, a.value, a.old) end
    end
  end
  for _, r in ipairs(refused) do
    io.stderr:write(string.format('[param] %s: refused %s\n', self.name, r.message))
  end
  if #applied > 0 and not self.quiet then io.stdout:flush() end
  if self.slot then
    local i = self.slot
    put(b.proc_concerns + i * CONCERNS, CONCERNS, table.concat(Config.loaded(), ','))
    b.proc_refused[i] = b.proc_refused[i] + #refused
    b.proc_seq[i] = seq
  end
end

-- Gives the slot back.
function Follower:leave()
  if self.slot then
    shm.C.shm_cas_i32(ffi.cast('volatile int32_t *', param_block().proc_pid) + self.slot, ffi.C.getpid(), 0)
    self.slot = nil
  end
end

-- param('walk.tStep') reads, param('walk.tStep', 0.3) sets.
return setmetatable(M, {
  __call = function(_, key, ...)
    if select('#', ...) == 0 then return M.get(key) end
    return M.set(key, (...))
  end,
})
