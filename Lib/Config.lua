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
--
-- What a concern's values must be (ranges, pairs, names from a set, rules across keys) is stated
-- once in Config/spec/<concern>.lua (a spec, see validate below), beside the defaults: every load
-- and export of the concern checks it, so the motion process, the REPL, tools and tests see the
-- same errors, each naming the file that set the key and the key's full path.
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

-- Overlays `src` (from `file`) onto `dst`. open: unknown keys may be added. origin: key path ->
-- the file that set it last (errors of a check name that file).
local function merge(dst, src, file, prefix, open, origin)
  for k, v in pairs(src) do
    local name = prefix .. tostring(k)
    local cur = dst[k]
    if cur == nil then
      if not open then
        error(string.format("%s: unknown key '%s' (no default layer has it)", file, name), 0)
      end
      dst[k] = copy(v)
      origin[name] = file
    elseif type(cur) ~= type(v) and cur ~= false then
      error(string.format("%s: key '%s' must be a %s, got %s", file, name, type(cur), type(v)), 0)
    elseif type(v) == 'table' and type(cur) == 'table' and not is_list(v) and not is_list(cur) then
      merge(cur, v, file, name .. '.', open, origin)
    else
      dst[k] = copy(v)
      origin[name] = file
    end
  end
end

-- The file that set key path `name` (or the table holding it); all the files when no layer did.
local function origin_of(origin, files, name)
  while name do
    if origin[name] then return origin[name] end
    name = name:match('^(.*)%.[^.]*$')
  end
  return files
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

-- Checks a concern's table against spec = { key = want }, want one of
--   'number' | 'string' | 'table' | 'boolean' | 'function'   the value's type
--   { nested spec }                                          a table, its keys checked the same way
--   check                                                    a function(value, cfg) -> true, or a
--       message ('must be a number in 0..1, got 2') and, for a part of the value, its key path
--       below key ('3.x'); value may be nil (the check says whether that is allowed), cfg is the
--       whole concern (rules across keys). A check may fill the documented defaults of a list's
--       elements (kick phases): layers cannot, as they replace lists whole.
-- where(name): the file(s) to name for key path `name`.
local function validate(tbl, spec, where, prefix, whole)
  for key, want in pairs(spec) do
    local v = rawget(tbl, key)
    local name = prefix .. key
    if type(want) == 'function' then
      local res, sub = want(v, whole)
      if res ~= true then
        if sub ~= nil then name = name .. '.' .. tostring(sub) end
        error(string.format("%s: key '%s' %s", where(name), name, tostring(res)), 0)
      end
    elseif v == nil then
      error(string.format("%s: missing key '%s'", where(name), name), 0)
    elseif type(want) == 'table' then
      if type(v) ~= 'table' then
        error(string.format("%s: key '%s' must be a table, got %s", where(name), name, type(v)), 0)
      end
      validate(v, want, where, name .. '.', whole)
    elseif type(v) ~= want then
      error(string.format("%s: key '%s' must be a %s, got %s", where(name), name, want, type(v)), 0)
    end
  end
end

-- The spec of a concern (Config/spec/<concern>.lua; a concern in a folder, wbc_skills/wave, without
-- a spec of its own: its folder's, Config/spec/wbc_skills.lua; nil: none).
local function concern_spec(concern)
  for _, name in ipairs({ concern, concern:match('^(.+)/[^/]+$') }) do
    local abs = config_root() .. '/Config/spec/' .. name .. '.lua'
    if exists(abs) then return read_file({ abs = abs, file = 'Config/spec/' .. name .. '.lua' }) end
  end
  return nil
end

-- robot.lua's per-joint tables (limits, actuator) name a joint that both sides have once: a key that
-- is no joint's name stands for the joints of that name with a side prefix (l_ and r_, or L and R:
-- `knee` for l_knee and r_knee, `HR` for LHR and RHR), each taking the value, or the left's and
-- the right's of { l = left's, r = right's }. Expanded as a body's file is read (the layer with
-- `joints`), so the layers above it and every reader see full joint names only.
local SIDES = { { 'l_', 'l' }, { 'r_', 'r' }, { 'L', 'l' }, { 'R', 'r' } }
local function expand_sides(t, file)
  if type(t.joints) ~= 'table' then return end
  local is_joint = {}
  for _, j in ipairs(t.joints) do is_joint[j] = true end
  for _, key in ipairs({ 'limits', 'actuator' }) do
    local tbl = t[key]
    if type(tbl) == 'table' then
      local short = {}
      for k, v in pairs(tbl) do
        if not is_joint[k] then short[k] = v end
      end
      for k, v in pairs(short) do
        tbl[k] = nil
        local found = false
        for _, side in ipairs(SIDES) do
          local j = side[1] .. k
          if is_joint[j] then
            found = true
            local per_side = type(v) == 'table' and (v.l ~= nil or v.r ~= nil)
            tbl[j] = copy(per_side and v[side[2]] or v)
          end
        end
        if not found then
          error(string.format("%s: key '%s.%s' names no joint (nor one of each side)", file, key, tostring(k)), 0)
        end
      end
    end
  end
end

-- Merges the layers of a concern: the plain table, the list of files used and the origin of
-- each key path (see merge).
local function build(concern, robot, platform)
  local result, used, has_default, origin = {}, {}, false, {}
  local ls = layers(concern, robot, platform)
  for _, l in ipairs(ls) do
    if l.default and exists(l.abs) then has_default = true end
  end
  for _, l in ipairs(ls) do
    local t = read_file(l)
    if t and concern == 'robot' then expand_sides(t, l.file) end
    if t then
      merge(result, t, l.file, '', l.default or (not has_default and #used == 0), origin)
      used[#used + 1] = l.file
    end
  end
  if #used == 0 then
    error(string.format("no config file for '%s' (robot %s, platform %s): looked for %s/%s.lua and %s/%s.lua",
      concern, robot, platform, robot_rel(robot), concern, platform_rel(platform), concern), 0)
  end
  return result, used, origin
end

-- build, then the concern's own spec (Config/spec/<concern>.lua) checked; also returns where(name).
local function build_checked(concern, robot, platform)
  local result, used, origin = build(concern, robot, platform)
  local files = table.concat(used, ' + ')
  local function where(name) return origin_of(origin, files, name) end
  local spec = concern_spec(concern)
  if spec then validate(result, spec, where, '', result) end
  return result, files, where
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
    local ok, res, files, where = pcall(build_checked, concern, robot, platform)
    if not ok then error(res, 2) end
    entry = { cfg = strict(res, files, ''), files = files, where = where }
    cache[key] = entry
  end
  if spec then
    local ok, err = pcall(validate, entry.cfg, spec, entry.where, '', entry.cfg)
    if not ok then error(err, 2) end
  end
  return entry.cfg
end

-- The file that set key path `key` ('tasks.com.gain') of a concern, or all of its files when no
-- layer did: for errors a caller finds beyond the spec (a frame the body lacks).
function M.origin(concern, key, opts)
  M.load(concern, nil, opts)
  local robot, platform = resolve(opts)
  return cache[concern .. '|' .. robot .. '|' .. platform].where(key)
end

-- The same as a plain table without metatables (for C readers and tools), plus the files used;
-- checked against the concern's spec as load does.
function M.export(concern, opts)
  local robot, platform = resolve(opts)
  local res, files = build_checked(concern, robot, platform)
  return res, files
end

-- Absolute path of a file named in a robot's config (relative to the robot's folder).
function M.robot_file(name, robot)
  if name:sub(1, 1) == '/' then return name end
  return M.robot_dir(robot) .. '/' .. name
end

-- A body's robot config, the absolute path of its description (robot.lua `description`, the URDF)
-- and the config's files, for messages (opts: nil = ROBOT, or { robot = name }).
function M.description(opts)
  local robot = M.load('robot', nil, opts)
  local files = table.concat(M.files('robot', opts), ' + ')
  local desc = rawget(robot, 'description')
  if type(desc) ~= 'string' then error(files .. ": missing key 'description' (the URDF)", 2) end
  local body = type(opts) == 'table' and opts.robot or M.robot()
  return robot, M.robot_file(desc, body), files
end

-- Builds a model of a body's description: new(robot config, URDF path, files) returns it, or nil
-- and a message naming the file and the element, which is raised.
function M.from_description(new, opts)
  local m, err = new(M.description(opts))
  if not m then error(err, 3) end
  return m
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
