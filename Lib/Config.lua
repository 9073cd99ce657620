-- Robot configuration, one concern (walk, robot, behavior, ...) at a time, overlaid from layers:
--
--   Config/common/<concern>.lua                   defaults for every robot (field, game, colours)
--   Config/robots/<ROBOT>/<concern>.lua           the body: description, walk, keyframes, sizes
--   Config/platforms/<PLATFORM>/<concern>.lua     what the platform changes (Sim: sim camera; OP: bus)
--   Config/platforms/<PLATFORM>/<ROBOT>/<concern>.lua   a platform's setting for one body (rare)
--   $HRP_SITE/<concern>.lua (default Config/site)  the venue: team and player number, colour table
--
-- A body whose robot.lua names a `base` body (a variant, a test body) takes every other concern
-- from the base's folder first, then its own file over it.
--
--   local Config = require('Config')
--   local walk = Config.load('walk', { tStep = 'number', stepLimitX = 'table' })
--   local other = Config.load('robot', nil, { robot = 'darwin' })
--
-- ROBOT (default op3) selects the body, PLATFORM (default Sim) the DCM. Each file returns a table.
-- The first two layers are defaults and may add keys; the platform and site layers only change
-- keys the defaults have (an unknown key there is a typo: an error naming the file and the key),
-- unless no default layer has the concern at all (sim.lua, dcm.lua). Tables merge key by key;
-- lists (tables with [1]) are replaced whole. A value keeps its type through the layers, except a
-- default of `false` ("none": a feature a body may have, e.g. walk.lua's `sole`), which any value
-- replaces. Every error names the file, and reading a key that
-- no layer has fails naming the files consulted (Config.optional reads optional keys).
local native = require('native')

local M = {}

local cache = {}
local bases = {} -- robot -> its base body's name, or false
local root -- nil: the project's root

-- Reads configs from another tree (tests); nil restores the project's root.
function M.use_root(dir) root = dir cache = {} bases = {} end
local function config_root() return root or native.root() end

local function env(name, default)
  local v = os.getenv(name)
  if v == nil or v == '' then return default end
  return v
end

function M.platform() return env('PLATFORM', 'Sim') end
function M.robot() return env('ROBOT', 'op3') end

-- Repository-relative folder of a robot's body and of a platform.
local function robot_rel(robot) return 'Config/robots/' .. robot end
local function platform_rel(platform) return 'Config/platforms/' .. platform end

-- Absolute path of Config/robots/<robot> (default ROBOT).
function M.robot_dir(robot) return config_root() .. '/' .. robot_rel(robot or M.robot()) end
-- Absolute path of the folder of a platform (default PLATFORM).
function M.dir(platform) return config_root() .. '/' .. platform_rel(platform or M.platform()) end

local function is_dir(path)
  local f = io.open(path .. '/.', 'r')
  if f then f:close() return true end
  return false
end

local function site_dir()
  local s = env('HRP_SITE', nil)
  if s then return s, s end
  return config_root() .. '/Config/site', 'Config/site'
end

-- opts: nil or { robot =, platform = } (each defaults to ROBOT / PLATFORM).
local function resolve(opts)
  opts = opts or {}
  local robot, platform = opts.robot or M.robot(), opts.platform or M.platform()
  if not is_dir(M.robot_dir(robot)) then
    error(string.format("unknown robot '%s': no folder %s", robot, robot_rel(robot)), 3)
  end
  if not is_dir(M.dir(platform)) then
    error(string.format("unknown platform '%s': no folder %s", platform, platform_rel(platform)), 3)
  end
  return robot, platform
end

-- The layers of a concern: { { abs = path, file = shown name, default = bool }, ... }
-- The body a robot's robot.lua names as its `base` (nil: none): a variant of a body takes every
-- concern but robot.lua (and keyframes) from its base unless it has its own file.
local function base_of(robot)
  local b = bases[robot]
  if b == nil then
    b = false
    local path = M.robot_dir(robot) .. '/robot.lua'
    local chunk = loadfile(path)
    local ok, t = false, nil
    if chunk then ok, t = pcall(chunk) end
    if ok and type(t) == 'table' and rawget(t, 'base') ~= nil then
      b = rawget(t, 'base')
      if type(b) ~= 'string' or not is_dir(M.robot_dir(b)) then
        error(string.format("%s/robot.lua: key 'base' must name a body in Config/robots, got %s", robot_rel(robot),
          tostring(b)), 0)
      end
    end
    bases[robot] = b
  end
  return b or nil
end

-- The folders of a body, its own first, then its base's (and theirs): Config/robots/<name> each.
function M.robot_chain(robot)
  local chain, seen = {}, {}
  robot = robot or M.robot()
  while robot and not seen[robot] do
    chain[#chain + 1] = robot
    seen[robot] = true
    robot = base_of(robot)
  end
  return chain
end

local function layers(concern, robot, platform)
  local site_abs, site_shown = site_dir()
  local r = config_root() .. '/'
  local name = concern .. '.lua'
  local ls = { { abs = r .. 'Config/common/' .. name, file = 'Config/common/' .. name, default = true } }
  local chain = concern == 'robot' and { robot } or M.robot_chain(robot)
  for k = #chain, 1, -1 do
    local rel = robot_rel(chain[k]) .. '/' .. name
    ls[#ls + 1] = { abs = r .. rel, file = rel, default = true }
  end
  ls[#ls + 1] = { abs = r .. platform_rel(platform) .. '/' .. name, file = platform_rel(platform) .. '/' .. name }
  ls[#ls + 1] = { abs = r .. platform_rel(platform) .. '/' .. robot .. '/' .. name,
    file = platform_rel(platform) .. '/' .. robot .. '/' .. name }
  ls[#ls + 1] = { abs = site_abs .. '/' .. name, file = site_shown .. '/' .. name }
  return ls
end

local function exists(path)
  local f = io.open(path, 'r')
  if f then f:close() return true end
  return false
end

local function read_file(layer)
  if not exists(layer.abs) then return nil end
  local chunk, err = loadfile(layer.abs)
  if not chunk then error(string.format('%s: %s', layer.file, err), 0) end
  local ok, res = pcall(chunk)
  if not ok then error(string.format('%s: %s', layer.file, tostring(res)), 0) end
  if type(res) ~= 'table' then
    error(string.format('%s: must return a table, returned %s', layer.file, type(res)), 0)
  end
  return res
end

local function is_list(t) return rawget(t, 1) ~= nil end

local function copy(v)
  if type(v) ~= 'table' then return v end
  local t = {}
  for k, x in pairs(v) do t[k] = copy(x) end
  return t
end

-- Overlays `src` (from `file`) onto `dst`. open: unknown keys may be added.
local function merge(dst, src, file, prefix, open)
  for k, v in pairs(src) do
    local name = prefix .. tostring(k)
    local cur = dst[k]
    if cur == nil then
      if not open then
        error(string.format("%s: unknown key '%s' (no default layer has it)", file, name), 0)
      end
      dst[k] = copy(v)
    elseif type(cur) ~= type(v) and cur ~= false then
      error(string.format("%s: key '%s' must be a %s, got %s", file, name, type(cur), type(v)), 0)
    elseif type(v) == 'table' and type(cur) == 'table' and not is_list(v) and not is_list(cur) then
      merge(cur, v, file, name .. '.', open)
    else
      dst[k] = copy(v)
    end
  end
end

-- Makes reading an absent key an error naming the files and the key path.
local function strict(tbl, files, prefix)
  for k, v in pairs(tbl) do
    if type(v) == 'table' and getmetatable(v) == nil then strict(v, files, prefix .. tostring(k) .. '.') end
  end
  return setmetatable(tbl, {
    __index = function(_, key)
      error(string.format("%s: missing key '%s%s'", files, prefix, tostring(key)), 2)
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

-- Merges the layers of a concern: the plain table and the list of files used.
local function build(concern, robot, platform)
  local result, used, has_default = {}, {}, false
  local ls = layers(concern, robot, platform)
  for _, l in ipairs(ls) do
    if l.default and exists(l.abs) then has_default = true end
  end
  for _, l in ipairs(ls) do
    local t = read_file(l)
    if t then
      merge(result, t, l.file, '', l.default or (not has_default and #used == 0))
      used[#used + 1] = l.file
    end
  end
  if #used == 0 then
    error(string.format("no config file for '%s' (robot %s, platform %s): looked for %s/%s.lua and %s/%s.lua",
      concern, robot, platform, robot_rel(robot), concern, platform_rel(platform), concern), 0)
  end
  return result, used
end

-- The files that make up a concern (repository-relative, lowest layer first).
function M.files(concern, opts)
  local robot, platform = resolve(opts)
  local _, used = build(concern, robot, platform)
  return used
end

-- Loads a concern (cached), checks it against spec (optional); a strict table.
function M.load(concern, spec, opts)
  local robot, platform = resolve(opts)
  local key = concern .. '|' .. robot .. '|' .. platform
  local entry = cache[key]
  if not entry then
    local ok, res, used = pcall(build, concern, robot, platform)
    if not ok then error(res, 2) end
    local files = table.concat(used, ' + ')
    entry = { cfg = strict(res, files, ''), files = files }
    cache[key] = entry
  end
  if spec then
    local ok, err = pcall(validate, entry.cfg, spec, entry.files, '')
    if not ok then error(err, 2) end
  end
  return entry.cfg
end

-- The same as a plain table without metatables (for C readers and tools), plus the files used.
function M.export(concern, opts)
  local robot, platform = resolve(opts)
  local res, used = build(concern, robot, platform)
  return res, table.concat(used, ' + ')
end

-- Absolute path of a file named in a robot's config (relative to the robot's folder).
function M.robot_file(name, robot)
  if name:sub(1, 1) == '/' then return name end
  return M.robot_dir(robot) .. '/' .. name
end

-- Value of an optional key (nil when absent) without tripping the strict check.
function M.optional(tbl, key, default)
  local v = rawget(tbl, key)
  if v == nil then return default end
  return v
end

-- The layer files of a concern that exist, lowest first: { { abs = path, file = shown name }, ... }
-- (Lib/param_save.lua writes a changed value into one of them).
function M.layers(concern, opts)
  local robot, platform = resolve(opts)
  local out = {}
  for _, l in ipairs(layers(concern, robot, platform)) do
    if exists(l.abs) then out[#out + 1] = { abs = l.abs, file = l.file, default = l.default } end
  end
  return out
end

-- The concerns this process has loaded for ROBOT / PLATFORM, sorted (Lib/param.lua applies live
-- changes to them: every module holding such a table sees the change).
function M.loaded()
  local robot, platform = M.robot(), M.platform()
  local out = {}
  for key in pairs(cache) do
    local c, r, p = key:match('^(.-)|(.-)|(.*)$')
    if r == robot and p == platform then out[#out + 1] = c end
  end
  table.sort(out)
  return out
end

-- Forget cached files (tests; re-reading a file edited at run time).
function M.reload() cache = {} bases = {} end

return M
