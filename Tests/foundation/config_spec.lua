-- luacheck: std +busted
-- Config loader: layers (common, robot, platform, platform x robot, site) and errors that name the
-- file and the key.
local Config = require('Config')

local files = require('Tests.files')

local tmp
local function write(path, text) files.write(tmp, path, text) end

local T = { robot = 'bot', platform = 'Test' }

describe('Config', function()
  files.config_root(function(dir)
    tmp = dir
    write('Config/robots/bot/walk.lua',
      'return { tStep = 0.25, limits = { vx = 0.3 }, name = "w", list = { 1, 2, 3 } }')
    write('Config/robots/bot/broken.lua', 'return { tStep = ')
    write('Config/robots/bot/notable.lua', 'return 42')
    write('Config/robots/other/walk.lua', 'return { tStep = 0.5, list = { 1 } }')
    write('Config/common/behavior.lua', 'return { team = 1, head = { pan = 1.0, tilt = 0.5 }, kick = true }')
    write('Config/robots/bot/behavior.lua', 'return { head = { pan = 1.2, range = 3 } }')
    write('Config/platforms/Test/behavior.lua', 'return { head = { tilt = 0.4 } }')
    write('Config/platforms/Test/bot/behavior.lua', 'return { team = 2 }')
    write('Config/platforms/Test/sim.lua', 'return { dt = 0.001 }')
    write('Config/platforms/Test/walk.lua', 'return { list = { 9 } }')
    write('Config/platforms/Bad/walk.lua', 'return { tSetp = 0.3 }')
    write('Config/platforms/Typed/walk.lua', 'return { limits = { vx = "fast" } }')
    write('Config/site/behavior.lua', 'return { team = 7 }')
    write('Config/common/feature.lua', 'return { sole = false, n = 1 }')
    write('Config/robots/bot/feature.lua', 'return { sole = { toe = 0.06 } }')
    write('Config/platforms/Test/feature.lua', 'return { sole = { toe = 0.07 } }')
    write('Config/platforms/Typed/feature.lua', 'return { n = false }')
    -- a concern with a spec (Config/spec/checked.lua): a range, a pair, a name from a set, a rule
    -- across keys, and list elements whose left-out fields are filled in
    write('Config/common/checked.lua',
      'return { gain = 1, pair = { 0, 1 }, mode = "a", lo = 0, hi = 1, steps = { { d = 1 } } }')
    write('Config/spec/checked.lua', [[
      local function num(v) return type(v) == 'number' end
      return {
        gain = function(v)
          return (num(v) and v >= 0 and v <= 10) or 'must be a number in 0..10, got ' .. tostring(v)
        end,
        pair = function(v) return (#v == 2 and v[1] < v[2]) or 'must be { lo, hi } with lo < hi' end,
        mode = function(v) return (v == 'a' or v == 'b') or "must be 'a' or 'b', got " .. tostring(v) end,
        lo = function(v, cfg) return v < cfg.hi or 'must be < hi (' .. cfg.hi .. ')' end,
        steps = function(v)
          for i, s in ipairs(v) do
            if not num(s.d) then return 'must be a number', i .. '.d' end
            if s.x == nil then s.x = 0 end
          end
          return true
        end,
      }]])
    write('Config/robots/bot/checked.lua', 'return { gain = 2, steps = { { d = 1 }, { d = 2, x = 3 } } }')
    write('Config/platforms/Range/checked.lua', 'return { gain = 11 }')
    write('Config/platforms/Pair/checked.lua', 'return { pair = { 2, 1 } }')
    write('Config/platforms/Enum/checked.lua', 'return { mode = "c" }')
    write('Config/platforms/Cross/checked.lua', 'return { lo = 2 }')
    write('Config/platforms/Steps/checked.lua', 'return { steps = { { d = 1 }, { d = "long" } } }')
  end)

  it('loads a file and checks types', function()
    local w = Config.load('walk', { tStep = 'number', limits = { vx = 'number' } }, T)
    assert.equal(0.25, w.tStep)
    assert.equal(0.3, w.limits.vx)
  end)

  it('overlays common, robot, platform, platform x robot and site, key by key', function()
    local b = Config.load('behavior', nil, T)
    assert.equal(1.2, b.head.pan)       -- robot over common
    assert.equal(3, b.head.range)       -- added by the robot layer
    assert.equal(0.4, b.head.tilt)      -- platform over common
    assert.equal(7, b.team)             -- site over platform x robot over common
    assert.is_true(b.kick)
    assert.same({ 'Config/common/behavior.lua', 'Config/robots/bot/behavior.lua',
      'Config/platforms/Test/behavior.lua', 'Config/platforms/Test/bot/behavior.lua', 'Config/site/behavior.lua' },
      Config.files('behavior', T))
  end)

  it('replaces lists whole', function()
    assert.same({ 9 }, Config.export('walk', T).list)
  end)

  it('a false default takes a value of any type; other values keep their type', function()
    assert.equal(0.07, Config.load('feature', nil, T).sole.toe)
    assert.same({ toe = 0.07 }, Config.export('feature', { robot = 'other', platform = 'Test' }).sole)
    assert.has_error(function() Config.load('feature', nil, { robot = 'bot', platform = 'Typed' }) end,
      "Config/platforms/Typed/feature.lua: key 'n' must be a number, got boolean")
  end)

  it('ROBOT selects the body', function()
    assert.equal(0.5, Config.load('walk', nil, { robot = 'other', platform = 'Test' }).tStep)
  end)

  it('a concern only a platform has is read from there', function()
    assert.equal(0.001, Config.load('sim', nil, T).dt)
  end)

  it('an overlay key the defaults do not have is an error naming the file and the key', function()
    local ok, err = pcall(Config.load, 'walk', nil, { robot = 'bot', platform = 'Bad' })
    assert.is_false(ok)
    assert.truthy(err:find("Config/platforms/Bad/walk.lua: unknown key 'tSetp'", 1, true), err)
  end)

  it('an overlay value of the wrong type names the file and the key', function()
    local ok, err = pcall(Config.load, 'walk', nil, { robot = 'bot', platform = 'Typed' })
    assert.is_false(ok)
    assert.truthy(err:find("Config/platforms/Typed/walk.lua: key 'limits.vx' must be a number, got string", 1, true),
      err)
  end)

  it('names files and key for a missing key in the spec', function()
    assert.has_error(function() Config.load('walk', { tDouble = 'number' }, T) end,
      "Config/robots/bot/walk.lua + Config/platforms/Test/walk.lua: missing key 'tDouble'")
  end)

  it('names the file that set the key for a wrong type, nested keys with their path', function()
    assert.has_error(function() Config.load('walk', { name = 'number' }, T) end,
      "Config/robots/bot/walk.lua: key 'name' must be a number, got string")
    assert.has_error(function() Config.load('walk', { limits = { vx = 'table' } }, T) end,
      "Config/robots/bot/walk.lua: key 'limits.vx' must be a table, got number")
  end)

  it('checks a concern against its spec on load and export, filling what a list element leaves out', function()
    local c = Config.load('checked', nil, T)
    assert.equal(2, c.gain)
    assert.same({ { d = 1, x = 0 }, { d = 2, x = 3 } }, Config.export('checked', T).steps)
    assert.equal(0, c.steps[1].x)
  end)

  it('names the file that set the key and the key for a value out of range, a bad pair, an unknown name, ' ..
    'a rule across keys, and a list element', function()
    local function fails(platform, msg)
      local opts = { robot = 'bot', platform = platform }
      assert.has_error(function() Config.load('checked', nil, opts) end, msg)
      assert.has_error(function() Config.export('checked', opts) end, msg)
    end
    fails('Range', "Config/platforms/Range/checked.lua: key 'gain' must be a number in 0..10, got 11")
    fails('Pair', "Config/platforms/Pair/checked.lua: key 'pair' must be { lo, hi } with lo < hi")
    fails('Enum', "Config/platforms/Enum/checked.lua: key 'mode' must be 'a' or 'b', got c")
    fails('Cross', "Config/platforms/Cross/checked.lua: key 'lo' must be < hi (1)")
    fails('Steps', "Config/platforms/Steps/checked.lua: key 'steps.2.d' must be a number")
  end)

  it('takes a check from the caller too', function()
    local function positive(v) return v > 0 or 'must be > 0' end
    assert.equal(0.25, Config.load('walk', { tStep = positive }, T).tStep)
    assert.has_error(function() Config.load('walk', { limits = { vx = function() return 'must be slow' end } }, T) end,
      "Config/robots/bot/walk.lua: key 'limits.vx' must be slow")
  end)

  it('fails when code reads a key no layer has', function()
    local w = Config.load('walk', nil, T)
    local ok, err = pcall(function() return w.limits.vy end)
    assert.is_false(ok)
    assert.truthy(err:find("Config/robots/bot/walk.lua + Config/platforms/Test/walk.lua: missing key 'limits.vy'", 1,
      true))
    assert.is_nil(Config.optional(w, 'absent'))
    assert.equal(7, Config.optional(w, 'absent', 7))
  end)

  it('names an unknown platform and an unknown robot', function()
    local ok, err = pcall(Config.load, 'walk', nil, { robot = 'bot', platform = 'Nope' })
    assert.is_false(ok)
    assert.truthy(err:find("unknown platform 'Nope'", 1, true))
    ok, err = pcall(Config.load, 'walk', nil, { robot = 'nobody', platform = 'Test' })
    assert.is_false(ok)
    assert.truthy(err:find("unknown robot 'nobody': no folder Config/robots/nobody", 1, true))
  end)

  it('names a missing concern, a syntax error and a file that returns no table', function()
    local ok, err = pcall(Config.load, 'camera', nil, T)
    assert.is_false(ok)
    assert.truthy(err:find("no config file for 'camera'", 1, true))
    ok, err = pcall(Config.load, 'broken', nil, T)
    assert.is_false(ok)
    assert.truthy(err:find('Config/robots/bot/broken.lua', 1, true))
    ok, err = pcall(Config.load, 'notable', nil, T)
    assert.is_false(ok)
    assert.truthy(err:find('Config/robots/bot/notable.lua: must return a table, returned number', 1, true))
  end)

  it('HRP_SITE names another site folder; a typo there is named', function()
    write('venue/behavior.lua', 'return { team_number = 42 }')
    write('typo/behavior.lua', 'return { team_numbr = 42 }')
    local function team(site)
      local h = io.popen('cd "$HRP_ROOT" && HRP_SITE=' .. tmp .. '/' .. site .. ' luajit -e \'local ok, b = ' ..
        'pcall(require("Config").export, "behavior") print(ok and b.team_number or b)\' 2>&1')
      local out = h:read('*a')
      h:close()
      return out
    end
    assert.equal('42\n', team('venue'))
    local err = team('typo')
    assert.truthy(err:find("typo/behavior.lua: unknown key 'team_numbr'", 1, true), err)
  end)

  it('PLATFORM and ROBOT select the folders; the defaults are Sim and op3', function()
    local h = io.popen('cd "$HRP_ROOT" && PLATFORM= ROBOT= luajit -e ' ..
      '\'local C = require("Config") print(C.platform(), C.robot())\'')
    assert.equal('Sim\top3', h:read('*l'))
    h:close()
    Config.use_root(nil)
    local robot = Config.load('robot', { joints = 'table' }, { robot = 'op3', platform = 'Sim' })
    assert.equal(20, #robot.joints)
    assert.equal('darwin', Config.load('robot', nil, { robot = 'darwin', platform = 'OP' }).name)
    Config.use_root(tmp)
  end)
end)
