-- luacheck: std +busted
-- The defaults live once: a body's walk.lua and robot.lua (Config/robots/<ROBOT>/) hold only what
-- differs from Config/common, and a `false` default (a feature some bodies have) takes a value of
-- any type.
local Config = require('Config')
local native = require('native')

local root = native.root()

local function same(a, b)
  if type(a) ~= 'table' or type(b) ~= 'table' then return a == b end
  for k, v in pairs(a) do if not same(v, b[k]) then return false end end
  for k in pairs(b) do if a[k] == nil then return false end end
  return true
end

-- The key paths of `body` whose value equals the default's (lists compared whole).
local function repeats(body, default, prefix, out)
  for k, v in pairs(body) do
    local d, name = default[k], prefix .. tostring(k)
    if type(v) == 'table' and type(d) == 'table' and v[1] == nil and d[1] == nil then
      repeats(v, d, name .. '.', out)
    elseif same(v, d) then
      out[#out + 1] = name
    end
  end
  return out
end

local function bodies()
  local out = {}
  local p = io.popen('ls "' .. root .. '/Config/robots"')
  for name in p:lines() do out[#out + 1] = name end
  p:close()
  return out
end

describe('Config defaults', function()
  for _, concern in ipairs({ 'walk', 'robot' }) do
    it(concern .. '.lua of every body repeats no default of Config/common/' .. concern .. '.lua', function()
      local default = dofile(root .. '/Config/common/' .. concern .. '.lua')
      for _, body in ipairs(bodies()) do
        local path = root .. '/Config/robots/' .. body .. '/' .. concern .. '.lua'
        local f = io.open(path)
        if f then
          f:close()
          local found = repeats(dofile(path), default, '', {})
          table.sort(found)
          assert.same({}, found, 'Config/robots/' .. body .. '/' .. concern .. '.lua repeats defaults')
        end
      end
    end)
  end

  it('gives every body a complete walk config (each key of the defaults, with its type or a feature)', function()
    local default = dofile(root .. '/Config/common/walk.lua')
    for _, body in ipairs(bodies()) do
      local w = Config.export('walk', { robot = body, platform = 'Sim' })
      for k, v in pairs(default) do
        assert.is_not_nil(w[k], body .. ': walk key ' .. k)
        if v ~= false then assert.equal(type(v), type(w[k]), body .. ': walk key ' .. k) end
      end
    end
  end)
end)
