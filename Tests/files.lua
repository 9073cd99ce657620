-- File helpers of the tests: whole files read and written, folders made on the way.
--   local files = require('Tests.files')
--   files.read(path)                 the file's bytes (an error if it cannot be opened)
--   files.write(root, path, text)    root/path with its folders, replacing what was there
local M = {}

function M.read(path)
  local f = assert(io.open(path, 'rb'))
  local s = f:read('*a')
  f:close()
  return s
end

function M.write(root, path, text)
  os.execute('mkdir -p "$(dirname ' .. root .. '/' .. path .. ')"')
  local f = assert(io.open(root .. '/' .. path, 'w'))
  f:write(text)
  f:close()
end

return M
