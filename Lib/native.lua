-- Finds the project's root, loads its native libraries (build/lib/libhrp<name>.so) once and
-- declares their C interfaces to the FFI from the modules' own headers.
local ffi = require('ffi')

local M = {}

local loaded = {}

-- The repository root: $HRP_ROOT, else the folder above this file's Lib/.
function M.root()
  local env = os.getenv('HRP_ROOT')
  if env and env ~= '' then return env end
  local src = debug.getinfo(1, 'S').source
  local dir = src:match('^@(.*)/Lib/[^/]*$')
  if dir then return dir end
  return '.'
end

-- ffi.load of build/lib/libhrp<name>.so, cached; a clear error if it was not built.
function M.load(name)
  local lib = loaded[name]
  if lib then return lib end
  local path = M.root() .. '/build/lib/libhrp' .. name .. '.so'
  local ok, res = pcall(ffi.load, path)
  if not ok then
    error(string.format("native library '%s' not loadable (%s): run `make` first", path, res), 2)
  end
  loaded[name] = res
  return res
end

-- Removes comments from C source; string and character literals are kept as they are.
local function strip_comments(src)
  local out, i, n = {}, 1, #src
  while i <= n do
    local s = src:find('[/"\']', i)
    if not s then out[#out + 1] = src:sub(i); break end
    out[#out + 1] = src:sub(i, s - 1)
    local c, c2 = src:sub(s, s), src:sub(s + 1, s + 1)
    if c == '/' and c2 == '*' then
      local e = src:find('*/', s + 2, true) or n - 1
      out[#out + 1] = ' '
      i = e + 2
    elseif c == '/' and c2 == '/' then
      i = src:find('\n', s, true) or n + 1
    elseif c == '/' then
      out[#out + 1] = c
      i = s + 1
    else
      local e = s + 1
      while e <= n and src:sub(e, e) ~= c do e = e + (src:sub(e, e) == '\\' and 2 or 1) end
      out[#out + 1] = src:sub(s, e)
      i = e + 1
    end
  end
  return table.concat(out)
end

-- The declarations of a C header as ffi.cdef takes them: without comments, preprocessor lines,
-- what stands under `#ifdef __cplusplus` (the extern "C" guard) and the bodies of static inline
-- functions (C-side helpers the FFI cannot declare).
function M.declarations(src)
  src = strip_comments(src):gsub('\\\n', ' ')
  local keep, skip = {}, 0
  for line in (src .. '\n'):gmatch('([^\n]*)\n') do
    local directive = line:match('^%s*#%s*(%a+)')
    if not directive then
      if skip == 0 then keep[#keep + 1] = line end
    elseif skip > 0 then
      if directive:match('^if') then skip = skip + 1 elseif directive == 'endif' then skip = skip - 1 end
    elseif line:match('^%s*#%s*ifdef%s+__cplusplus%s*$') then
      skip = 1
    end
  end
  local decl = table.concat(keep, '\n')
  while true do
    local s = decl:find('static%s+inline')
    if not s then break end
    local depth, e = 0, decl:find('{', s, true)
    repeat
      local c = decl:sub(e, e)
      if c == '{' then depth = depth + 1 elseif c == '}' then depth = depth - 1 end
      e = e + 1
    until depth == 0 or e > #decl
    decl = decl:sub(1, s - 1) .. decl:sub(e)
  end
  return decl
end

local declared = {}

-- ffi.cdef of Modules/<dir>/<file>.h (file defaults to dir), once: the header is the one place
-- a module's C interface is written, for C callers and for LuaJIT alike.
function M.cdef(dir, file)
  local path = M.root() .. '/Modules/' .. dir .. '/' .. (file or dir) .. '.h'
  if declared[path] then return end
  local f, err = io.open(path, 'r')
  if not f then error(string.format("C header '%s' not readable (%s)", path, err), 2) end
  local src = f:read('*a')
  f:close()
  ffi.cdef(M.declarations(src))
  declared[path] = true
end

return M
