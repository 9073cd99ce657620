-- Finds the project's root and loads its native libraries (build/lib/libhrp<name>.so) once.
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

return M
