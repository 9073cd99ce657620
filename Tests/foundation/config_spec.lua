-- luacheck: std +busted
-- Config loader: errors name the file and the key.
local Config = require('Config')

local tmp
local function write(path, text)
  os.execute('mkdir -p "$(dirname ' .. tmp .. '/' .. path .. ')"')
  local f = assert(io.open(tmp .. '/' .. path, 'w'))
  f:write(text)
  f:close()
end

describe('Config', function()
  setup(function()
    tmp = os.tmpname()
    os.remove(tmp)
    write('Config/Test/walk.lua', 'return { tStep = 0.25, limits = { vx = 0.3 }, name = "w" }')
    write('Config/Test/broken.lua', 'return { tStep = ')
    write('Config/Test/notable.lua', 'return 42')
    Config.use_root(tmp)
  end)
  teardown(function()
    Config.use_root(nil)
    os.execute('rm -rf ' .. tmp)
  end)

  it('loads a file and checks types', function()
    local w = Config.load('walk', { tStep = 'number', limits = { vx = 'number' } }, 'Test')
    assert.equal(0.25, w.tStep)
    assert.equal(0.3, w.limits.vx)
  end)

  it('names file and key for a missing key in the spec', function()
    assert.has_error(function() Config.load('walk', { tDouble = 'number' }, 'Test') end,
      "Config/Test/walk.lua: missing key 'tDouble'")
  end)

  it('names file and key for a wrong type, nested keys with their path', function()
    assert.has_error(function() Config.load('walk', { name = 'number' }, 'Test') end,
      "Config/Test/walk.lua: key 'name' must be a number, got string")
    assert.has_error(function() Config.load('walk', { limits = { vx = 'table' } }, 'Test') end,
      "Config/Test/walk.lua: key 'limits.vx' must be a table, got number")
  end)

  it('fails when code reads a key the file does not have', function()
    local w = Config.load('walk', nil, 'Test')
    local ok, err = pcall(function() return w.limits.vy end)
    assert.is_false(ok)
    assert.truthy(err:find("Config/Test/walk.lua: missing key 'limits.vy'", 1, true))
    assert.is_nil(Config.optional(w, 'absent'))
    assert.equal(7, Config.optional(w, 'absent', 7))
  end)

  it('names an unknown platform', function()
    local ok, err = pcall(Config.load, 'walk', nil, 'Nope')
    assert.is_false(ok)
    assert.truthy(err:find("unknown platform 'Nope'", 1, true))
  end)

  it('names a missing file, a syntax error and a file that returns no table', function()
    local ok, err = pcall(Config.load, 'camera', nil, 'Test')
    assert.is_false(ok)
    assert.truthy(err:find('Config/Test/camera.lua: missing config file', 1, true))
    ok, err = pcall(Config.load, 'broken', nil, 'Test')
    assert.is_false(ok)
    assert.truthy(err:find('broken.lua', 1, true))
    ok, err = pcall(Config.load, 'notable', nil, 'Test')
    assert.is_false(ok)
    assert.truthy(err:find('Config/Test/notable.lua: must return a table, returned number', 1, true))
  end)

  it('PLATFORM selects the folder; the default is Sim', function()
    local h = io.popen('cd "$HRP_ROOT" && PLATFORM= luajit -e \'print(require("Config").platform())\'')
    assert.equal('Sim', h:read('*l'))
    h:close()
    Config.use_root(nil)
    local robot = Config.load('robot', { joints = 'table' }, 'Sim')
    assert.equal(20, #robot.joints)
    Config.use_root(tmp)
  end)
end)
