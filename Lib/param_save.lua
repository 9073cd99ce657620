-- Writes a changed config value back into its Lua source, in place: only the value's text changes,
-- comments, layout and every other key stay as they were (Lib/param.lua's param.save).
--
--   local save = require('param_save')
--   save.write('walk', { 'tStep' }, 0.3)          -- -> 'Config/robots/op3/walk.lua'
--   save.edit(source, { 'ball', 'max_range' }, 4)  -- the edited source text (or nil, message)
--
-- Which file: the highest layer (Lib/Config.lua: common, robot, platform, platform x robot, site)
-- whose file sets the key. The value in force came from there, so that is where it changes, and
-- no layer above hides the new value. A key set only by Config/common is written there (a default
-- of every body): to keep a value for one body or one venue, add the key to that layer's file first.
-- The file must end in `return { ... }` (every config file does); the value replaced is the text of
-- the key's expression in that table. The edited file is loaded again and compared with the old one
-- before it replaces it: the key must read the new value and nothing else may differ.
local Config = require('Config')

local M = {}

-- ---- tokens: { t = kind, s = first byte, e = last byte, v = text }

local function long_bracket(src, i)
  local eq = src:match('^%[(=*)%[', i)
  if not eq then return nil end
  local close = ']' .. eq .. ']'
  local _, e = src:find(close, i + #eq + 2, true)
  return e or #src
end

local function tokenize(src)
  local toks, i, n = {}, 1, #src
  while i <= n do
    local c = src:sub(i, i)
    if c:match('%s') then
      i = i + 1
    elseif src:sub(i, i + 1) == '--' then
      local e = long_bracket(src, i + 2)
      if e then i = e + 1
      else
        local nl = src:find('\n', i, true)
        i = (nl or n) + 1
      end
    elseif c == '"' or c == "'" then
      local j = i + 1
      while j <= n and src:sub(j, j) ~= c do
        if src:sub(j, j) == '\\' then j = j + 1 end
        j = j + 1
      end
      toks[#toks + 1] = { t = 'string', s = i, e = j, v = src:sub(i, j) }
      i = j + 1
    elseif c == '[' and long_bracket(src, i) then
      local e = long_bracket(src, i)
      toks[#toks + 1] = { t = 'string', s = i, e = e, v = src:sub(i, e) }
      i = e + 1
    elseif c:match('%d') or (c == '.' and src:sub(i + 1, i + 1):match('%d')) then
      local e = select(2, src:find('^0[xX][%x%.]+[pP][%+%-]?%d+', i))
        or select(2, src:find('^0[xX][%x%.]+', i))
        or select(2, src:find('^%d*%.?%d*[eE][%+%-]?%d+', i))
        or select(2, src:find('^%d*%.?%d*', i))
      toks[#toks + 1] = { t = 'number', s = i, e = e, v = src:sub(i, e) }
      i = e + 1
    elseif c:match('[%a_]') then
      local s, e = src:find('^[%w_]+', i)
      toks[#toks + 1] = { t = 'name', s = s, e = e, v = src:sub(s, e) }
      i = e + 1
    else
      local three, two = src:sub(i, i + 2), src:sub(i, i + 1)
      local op = (three == '...' and three) or
        ((two == '..' or two == '==' or two == '~=' or two == '<=' or two == '>=' or two == '::') and two) or c
      toks[#toks + 1] = { t = 'op', s = i, e = i + #op - 1, v = op }
      i = i + #op
    end
  end
  return toks
end

local OPEN = { ['('] = true, ['{'] = true, ['['] = true, ['function'] = true, ['if'] = true, ['do'] = true,
  ['repeat'] = true }
local CLOSE = { [')'] = true, ['}'] = true, [']'] = true, ['end'] = true, ['until'] = true }
local function opens(tok) return OPEN[tok.v] and (tok.t == 'op' or tok.t == 'name') end
local function closes(tok) return CLOSE[tok.v] and (tok.t == 'op' or tok.t == 'name') end

-- Index of the token closing the bracket or block opened at i.
local function matching(toks, i)
  local depth = 0
  for k = i, #toks do
    if opens(toks[k]) then depth = depth + 1
    elseif closes(toks[k]) then
      depth = depth - 1
      if depth == 0 then return k end
    end
  end
  return nil
end

-- Last token of the expression starting at i (up to a ',' ';' or '}' at its own level).
local function expr_end(toks, i)
  local depth, k = 0, i
  while k <= #toks do
    local t = toks[k]
    if depth == 0 and t.t == 'op' and (t.v == ',' or t.v == ';' or t.v == '}') then return k - 1 end
    if opens(t) then depth = depth + 1 elseif closes(t) then depth = depth - 1 end
    k = k + 1
  end
  return #toks
end

local function literal_key(tok)
  if tok.t == 'number' then return tonumber(tok.v) end
  if tok.t == 'string' then
    local f = loadstring('return ' .. tok.v)
    return f and f()
  end
  return nil
end

-- Records in spans[path] = { first, last } the expression of every field of the table constructor
-- opening at i (recursively, also into a table a field names by a top-level `local NAME = { ... }`:
-- locals[NAME] = index of its '{'); returns the index of its closing '}'.
local function fields(toks, i, prefix, spans, locals, inside)
  local k, pos = i + 1, 0
  while k <= #toks and toks[k].v ~= '}' do
    local t, key, vstart = toks[k], nil, k
    if t.t == 'name' and toks[k + 1] and toks[k + 1].v == '=' and toks[k + 1].t == 'op' then
      key, vstart = t.v, k + 2
    elseif t.t == 'op' and t.v == '[' then
      local close = matching(toks, k)
      if close == k + 2 then key = literal_key(toks[k + 1]) end
      vstart = close + 2
    else
      pos = pos + 1
      key = pos
    end
    local vend = expr_end(toks, vstart)
    if key ~= nil then
      local path = prefix .. '\0' .. tostring(key)
      spans[path] = { vstart, vend }
      local v = toks[vstart]
      if v.v == '{' and matching(toks, vstart) == vend then fields(toks, vstart, path, spans, locals, inside)
      elseif vstart == vend and v.t == 'name' and locals[v.v] and not inside[v.v] then
        inside[v.v] = true
        fields(toks, locals[v.v], path, spans, locals, inside)
        inside[v.v] = nil
      end
    end
    k = vend + 1
    if toks[k] and (toks[k].v == ',' or toks[k].v == ';') then k = k + 1 end
  end
  return k
end

-- The spans of every key of the table the source returns (its last statement, `return { ... }`).
local function parse(src)
  local toks = tokenize(src)
  -- top-level `local NAME = {`: outside any block or bracket
  local locals, depth = {}, 0
  for k = 1, #toks do
    local t = toks[k]
    if depth == 0 and t.v == 'local' and toks[k + 3] and toks[k + 1].t == 'name' and toks[k + 2].v == '='
       and toks[k + 3].v == '{' then
      locals[toks[k + 1].v] = k + 3
    end
    if opens(t) then depth = depth + 1 elseif closes(t) then depth = depth - 1 end
  end
  for k = #toks - 1, 1, -1 do
    if toks[k].t == 'name' and toks[k].v == 'return' and toks[k + 1].v == '{' and matching(toks, k + 1) == #toks then
      local spans = {}
      fields(toks, k + 1, '', spans, locals, {})
      return toks, spans
    end
  end
  return nil, 'the file does not end in `return { ... }`'
end

local function path_string(path)
  local parts = {}
  for i, p in ipairs(path) do parts[i] = tostring(p) end
  return '\0' .. table.concat(parts, '\0')
end

-- ---- values as Lua source

local function number(v)
  if v == math.floor(v) and math.abs(v) < 1e15 then return string.format('%d', v) end
  for digits = 15, 17 do
    local s = string.format('%.' .. digits .. 'g', v)
    if tonumber(s) == v then return s end
  end
  return string.format('%.17g', v)
end

function M.format(v)
  local t = type(v)
  if t == 'number' then return number(v) end
  if t == 'boolean' then return tostring(v) end
  if t == 'string' then return string.format('%q', v) end
  if t == 'table' then
    local parts = {}
    for i, x in ipairs(v) do parts[i] = M.format(x) end
    return '{ ' .. table.concat(parts, ', ') .. ' }'
  end
  error('param_save: cannot write a ' .. t, 2)
end

-- True when the source sets path (a key of its returned table).
function M.sets(src, path)
  local _, spans = parse(src)
  return spans ~= nil and spans[path_string(path)] ~= nil
end

-- The source with the value of path replaced by value's text, or nil and a message.
function M.edit(src, path, value)
  local toks, spans = parse(src)
  if not toks then return nil, spans end
  local span = spans[path_string(path)]
  if not span then return nil, "the file's returned table does not set the key" end
  local first, last = toks[span[1]], toks[span[2]]
  return src:sub(1, first.s - 1) .. M.format(value) .. src:sub(last.e + 1)
end

-- ---- checking the edited file

local function run(src, name)
  local chunk, err = loadstring(src, '=' .. name)
  if not chunk then return nil, err end
  local ok, res = pcall(chunk)
  if not ok then return nil, tostring(res) end
  if type(res) ~= 'table' then return nil, 'does not return a table' end
  return res
end

-- The first difference between a and b (nil when equal), functions counted equal.
local function differs(a, b, name)
  if type(a) ~= type(b) then return name end
  if type(a) == 'function' then return nil end
  if type(a) ~= 'table' then
    if a ~= b then return name end
    return nil
  end
  for k, v in pairs(a) do
    local d = differs(v, b[k], name .. '.' .. tostring(k))
    if d then return d end
  end
  for k in pairs(b) do
    if a[k] == nil then return name .. '.' .. tostring(k) end
  end
  return nil
end

-- Checks that new_src reads like old_src but for path, which reads value.
function M.verify(old_src, new_src, path, value, name)
  local old, err = run(old_src, name)
  if not old then return nil, 'the file before the edit: ' .. err end
  local new
  new, err = run(new_src, name)
  if not new then return nil, 'the edited file: ' .. err end
  local parent_old, parent_new = old, new
  for i = 1, #path - 1 do parent_old, parent_new = parent_old[path[i]], parent_new[path[i]] end
  local key = path[#path]
  local d = differs(value, parent_new[key], 'value')
  if d then return nil, 'the edited file does not read the new value' end
  parent_new[key] = parent_old[key]
  d = differs(old, new, '')
  if d then return nil, "the edit changed another key: '" .. d:sub(2) .. "'" end
  return true
end

local function read_all(path)
  local f = io.open(path, 'rb')
  if not f then return nil end
  local s = f:read('*a')
  f:close()
  return s
end

-- The layer file (Config.layers) that a change of concern's path is written into: the highest one
-- that sets it. Returns the layer, or nil and a message.
function M.target(concern, path, opts)
  local ls = Config.layers(concern, opts)
  for i = #ls, 1, -1 do
    local src = read_all(ls[i].abs)
    if src and M.sets(src, path) then return ls[i] end
  end
  local files = {}
  for i, l in ipairs(ls) do files[i] = l.file end
  return nil, string.format("no file of '%s' sets '%s' in its returned table (%s)", concern,
    table.concat(path, '.'), table.concat(files, ' + '))
end

-- Writes value for concern's path into its file (M.target); returns the file's repository name.
-- Errors name the file and the key.
function M.write(concern, path, value, opts)
  local key = concern .. '.' .. table.concat(path, '.')
  local layer, err = M.target(concern, path, opts)
  if not layer then error('param.save: ' .. err, 2) end
  local old = read_all(layer.abs)
  local new
  new, err = M.edit(old, path, value)
  if new then
    local ok
    ok, err = M.verify(old, new, path, value, layer.file)
    if not ok then new = nil end
  end
  if not new then error(string.format("param.save: %s: '%s': %s", layer.file, key, err), 2) end
  if new == old then return layer.file end
  local tmp = layer.abs .. '.param-save'
  local f = assert(io.open(tmp, 'wb'))
  f:write(new)
  f:close()
  local ok, rerr = os.rename(tmp, layer.abs)
  if not ok then
    os.remove(tmp)
    error(string.format('param.save: %s: %s', layer.file, tostring(rerr)), 2)
  end
  return layer.file
end

return M
