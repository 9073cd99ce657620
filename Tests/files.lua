-- File helpers of the tests: whole files read and written, folders made on the way, a Config tree
-- of a spec's own.
--   local files = require('Tests.files')
--   files.read(path)                 the file's bytes (an error if it cannot be opened)
--   files.write(root, path, text)    root/path with its folders, replacing what was there
--   files.config_root(fill)          in a describe block: before its tests, a fresh folder that
--                                    fill(dir) writes Config files into, and Config reading from
--                                    it; after them, Config back on the tree and the folder removed
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

function M.config_root(fill)
  local Config = require('Config')
  -- busted's setup and teardown live in the calling spec's environment, not in this module's
  local busted = getfenv(2)
  local dir
  busted.setup(function()
    dir = os.tmpname()
    os.remove(dir)
    fill(dir)
    Config.use_root(dir)
  end)
  busted.teardown(function()
    Config.use_root(nil)
    os.execute('rm -rf ' .. dir)
  end)
end

return M
