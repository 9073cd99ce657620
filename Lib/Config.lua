-- Robot configuration: Config/<PLATFORM>/<concern>.lua, each a Lua file returning a table.
--
--   local Config = require('Config')
--   local walk = Config.load('walk', { tStep = 'number', stanceLimitX = 'table' })
--
-- PLATFORM (default Sim) selects the folder. A missing file, a missing key, a key of the
-- wrong type or an unknown platform fails at once with the file and the key named; reading a
-- key that the file does not have also fails (use Config.optional for optional keys).
local native = require('native')

local M = {}

local cache = {}
local root -- nil: the project's root

-- Reads configs from another tree (tests); nil restores the project's root.
function M.use_root(dir) root = dir cache = {} end
local function config_root() return root or native.root() end

function M.platform()
  local p = os.getenv('PLATFORM')
  if p == nil or p == '' then return 'Sim' end
  return p
end

function M.dir(platform)
  return config_root() .. '/Config/' .. (platform or M.platform())
end

local function is_dir(path)
  local f = io.open(path .. '/.', 'r')
  if f then f:close() return true end
  return false
end

-- Makes reading an absent key an error naming the file and the key path.
local function strict(tbl, file, prefix)
  for k, v in pairs(tbl) do
    if type(v) == 'table' and getmetatable(v) == nil then strict(v, file, prefix .. tostring(k) .. '.') end
  end
  return setmetatable(tbl, {
    __index = function(_, key)
      error(string.format("%s: missing key '%s%s'", file, prefix, tostring(key)), 2)
    end,
  })
end

-- Checks spec = { key = 'number' | 'string' | 'table' | 'boolean' | 'function' | {nested spec} }.
local function validate(tbl, spec, file, prefix)
  for key, want in pairs(spec) do
    local v = rawget(tbl, key)
    local name = prefix .. key
    if v == nil then error(string.format("%s: missing key '%s'", file, name), 0) end
    if type(want) == 'table' then
      if type(v) ~= 'table' then
        error(string.format("%s: key '%s' must be a table, got %s", file, name, type(v)), 0)
      end
      validate(v, want, file, name .. '.')
    elseif type(v) ~= want then
      error(string.format("%s: key '%s' must be a %s, got %s", file, name, want, type(v)), 0)
    end
  end
end

-- Loads Config/<platform>/<concern>.lua (cached), checks it against spec (optional).
function M.load(concern, spec, platform)
  platform = platform or M.platform()
  local dir = M.dir(platform)
  if not is_dir(dir) then
    error(string.format("unknown platform '%s': no folder %s", platform, dir), 2)
  end
  local file = 'Config/' .. platform .. '/' .. concern .. '.lua'
  local cfg = cache[file]
  if not cfg then
    local chunk, err = loadfile(config_root() .. '/' .. file)
    if not chunk then
      if err:find('No such file') or err:find('cannot open') then
        error(string.format("%s: missing config file for '%s' on platform %s", file, concern, platform), 2)
      end
      error(string.format('%s: %s', file, err), 2)
    end
    local ok, res = pcall(chunk)
    if not ok then error(string.format('%s: %s', file, res), 2) end
    if type(res) ~= 'table' then error(string.format('%s: must return a table, returned %s', file, type(res)), 2) end
    cfg = strict(res, file, '')
    cache[file] = cfg
  end
  if spec then
    local ok, err = pcall(validate, cfg, spec, file, '')
    if not ok then error(err, 2) end
  end
  return cfg
end

local function plain_copy(v)
  if type(v) ~= 'table' then return v end
  local t = {}
  for k, x in pairs(v) do t[k] = plain_copy(x) end
  return t
end

-- The merged table as a plain deep copy (no metatables), for C readers (Modules/dcm).
function M.export(concern, opts)
  opts = opts or {}
  return plain_copy(M.load(concern, nil, opts.platform))
end

-- The files a concern is read from (repo-relative), for messages.
function M.files(concern, opts)
  opts = opts or {}
  return { 'Config/' .. (opts.platform or M.platform()) .. '/' .. concern .. '.lua' }
end

-- Value of an optional key (nil when absent) without tripping the strict check.
function M.optional(tbl, key, default)
  local v = rawget(tbl, key)
  if v == nil then return default end
  return v
end

-- Forget cached files (tests; re-reading a file edited at run time).
function M.reload() cache = {} end

return M
