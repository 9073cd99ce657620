-- The configuration in force as JSON, one document per concern, for the recorder's attachments
-- (Run/recorder/config_dump.c runs this in an embedded LuaJIT):
--   require('Run.config_dump')({ 'robot', 'walk' }) -> { { name = 'robot', json = '{...}', files = '...' }, ... }
-- A concern without any config file is left out; any other error is raised.
local Config = require('Config')

local function is_list(t)
  local n = 0
  for _ in pairs(t) do n = n + 1 end
  return n > 0 and n == #t
end

local function quote(s)
  return '"' .. s:gsub('[%c"\\]', function(c)
    local named = { ['"'] = '\\"', ['\\'] = '\\\\', ['\n'] = '\\n', ['\t'] = '\\t', ['\r'] = '\\r' }
    return named[c] or string.format('\\u%04x', c:byte())
  end) .. '"'
end

local encode
local function number(v)
  if v ~= v then return '"nan"' end            -- JSON has no NaN / infinity: as strings
  if v == math.huge then return '"inf"' end
  if v == -math.huge then return '"-inf"' end
  if v == math.floor(v) and math.abs(v) < 2 ^ 53 then return string.format('%d', v) end
  return string.format('%.17g', v)
end

function encode(v, out)
  local t = type(v)
  if t == 'table' then
    if is_list(v) then
      out[#out + 1] = '['
      for i, x in ipairs(v) do
        if i > 1 then out[#out + 1] = ',' end
        encode(x, out)
      end
      out[#out + 1] = ']'
    else
      local keys = {}
      for k in pairs(v) do keys[#keys + 1] = tostring(k) end
      table.sort(keys)
      out[#out + 1] = '{'
      for i, k in ipairs(keys) do
        if i > 1 then out[#out + 1] = ',' end
        out[#out + 1] = quote(k) .. ':'
        local x = v[k]
        if x == nil then x = v[tonumber(k)] end
        encode(x, out)
      end
      out[#out + 1] = '}'
    end
  elseif t == 'number' then out[#out + 1] = number(v)
  elseif t == 'string' then out[#out + 1] = quote(v)
  elseif t == 'boolean' then out[#out + 1] = tostring(v)
  else out[#out + 1] = quote('<' .. t .. '>')   -- functions in a config: named, not lost silently
  end
end

return function(concerns)
  local docs = {}
  for _, name in ipairs(concerns) do
    local ok, tbl, files = pcall(Config.export, name)
    if ok then
      local out = {}
      encode(tbl, out)
      docs[#docs + 1] = { name = name, json = table.concat(out), files = files }
    elseif not tostring(tbl):find('^no config file for') then
      error(tbl, 0)
    end
  end
  return docs
end
