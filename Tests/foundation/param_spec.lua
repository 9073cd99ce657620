-- luacheck: std +busted
-- Live parameters (Lib/param.lua) and saving them into the config files (Lib/param_save.lua).
local Config = require('Config')
local save = require('param_save')
local native = require('native')

local testfiles = require('Tests.files')
local read = testfiles.read

-- A fresh copy of Lib/param.lua: its own view of the changes, as another process has.
local function fresh_param()
  package.loaded['param'] = nil
  return require('param')
end

describe('param_save.edit', function()
  it('edits every leaf of every config file in the repository, changing only that key', function()
    local files = io.popen('cd ' .. native.root() .. ' && find Config -name "*.lua" | sort'):read('*a')
    local edited, checked = 0, 0
    for file in files:gmatch('[^\n]+') do
      -- whole-body skills are choreography written with functions (a task built once, used in many
      -- states): every leaf is still checked never to be edited wrongly, but they do not count in the
      -- share of leaves edited in place, which is about the parameter files
      local counted = not file:match('/wbc_skills/')
      local src = read(native.root() .. '/' .. file)
      local t = assert(loadstring(src, '=' .. file))()
      local function visit(v, path)
        local new
        if type(v) == 'number' then new = v + 1.5
        elseif type(v) == 'boolean' then new = not v
        elseif type(v) == 'string' then new = v .. '_x'
        elseif type(v) == 'table' then
          local list = #v > 0
          for _, x in ipairs(v) do if type(x) ~= 'number' then list = false end end
          if list then
            new = {}
            for i, x in ipairs(v) do new[i] = x * 2 + 1 end
          end
          for k, x in pairs(v) do
            local p = { unpack(path) }
            p[#p + 1] = k
            visit(x, p)
          end
        end
        if new == nil or #path == 0 then return end
        if counted then checked = checked + 1 end
        local out, err = save.edit(src, path, new)
        -- a value built by code (a function's result, a local shared by two keys) is refused, never
        -- edited wrongly: save.write writes only what save.verify accepts
        if out then
          local ok, verr = save.verify(src, out, path, new, file)
          if ok then edited = edited + (counted and 1 or 0) else assert.matches('changed another key', verr) end
        else
          assert.matches('does not set the key', err)
        end
      end
      visit(t, {})
    end
    print(string.format('# param_save: %d of %d leaves of the Config files edited in place', edited, checked))
    assert.is_true(edited > 500)
    -- most leaves are literal; the rest are built by code on purpose (a body deriving rows from another's
    -- layout, as the DARwIn-OP's servo rows from the OP3's ROBOTIS ids), edited where they are written
    assert.is_true(edited >= checked * 0.75, string.format('%d of %d', edited, checked))
  end)

  it('keeps comments and layout: only the value text changes', function()
    local src = '-- the walk\nreturn {\n  tStep = 0.25,   -- s, one step\n  -- lists\n' ..
      '  limits = { 1, 2 }, x = "a",\n' ..
      '  nested = { deep = { v = 2e-3 } }, ["odd key"] = true,\n}\n'
    assert.equal(src:gsub('0%.25', '0.3'), save.edit(src, { 'tStep' }, 0.3))
    assert.equal(src:gsub('{ 1, 2 }', '{ 3, 4.5 }'), save.edit(src, { 'limits' }, { 3, 4.5 }))
    assert.equal(src:gsub('{ 1, 2 }', '{ 1, 7 }'), save.edit(src, { 'limits', 2 }, 7))
    assert.equal(src:gsub('2e%-3', '0.1'), save.edit(src, { 'nested', 'deep', 'v' }, 0.1))
    assert.equal(src:gsub('= true', '= false'), save.edit(src, { 'odd key' }, false))
    assert.equal(src:gsub('"a"', '"b c"'), save.edit(src, { 'x' }, 'b c'))
    assert.equal('return { a = 0.1 }', save.edit('return { a = 1 }', { 'a' }, 0.1))
    assert.equal('return { a = 0.30000000000000004 }', save.edit('return { a = 1 }', { 'a' }, 0.1 + 0.2))
    assert.is_nil((save.edit(src, { 'nothere' }, 1)))
    assert.is_nil((save.edit('local t = {}\nt.a = 1\nreturn t', { 'a' }, 2)))
  end)
end)

describe('param_save.write', function()
  local tmp
  local function write(path, text) testfiles.write(tmp, path, text) end
  local T = { robot = 'bot', platform = 'Test' }
  testfiles.config_root(function(dir)
    tmp = dir
    write('Config/common/vision.lua',
      'return {\n  ball = { max_range = 6.0, -- m\n    diameter = 0.14 },\n  lut = "a.lut",\n}\n')
    write('Config/robots/bot/robot.lua', 'return { joints = {} }')
    write('Config/robots/bot/vision.lua', 'return { ball = { diameter = 0.2 } } -- a bigger ball')
    write('Config/platforms/Test/dcm.lua', 'return { }')
    write('Config/site/vision.lua', 'return { lut = "b.lut" }')
  end)

  it('writes into the highest layer that sets the key', function()
    assert.equal('Config/robots/bot/vision.lua', save.write('vision', { 'ball', 'diameter' }, 0.16, T))
    assert.equal('return { ball = { diameter = 0.16 } } -- a bigger ball', read(tmp .. '/Config/robots/bot/vision.lua'))
    assert.equal('Config/common/vision.lua', save.write('vision', { 'ball', 'max_range' }, 4.5, T))
    assert.equal('return {\n  ball = { max_range = 4.5, -- m\n    diameter = 0.14 },\n  lut = "a.lut",\n}\n',
      read(tmp .. '/Config/common/vision.lua'))
    assert.equal('Config/site/vision.lua', save.write('vision', { 'lut' }, 'x.lut', T))
    assert.equal('return { lut = "x.lut" }', read(tmp .. '/Config/site/vision.lua'))
    Config.reload()
    local v = Config.load('vision', nil, T)
    assert.equal(0.16, v.ball.diameter)
    assert.equal(4.5, v.ball.max_range)
    assert.equal('x.lut', v.lut)
  end)

  it('refuses a key no file sets, naming it', function()
    assert.has_error(function() save.write('vision', { 'ball', 'colour' }, 1, T) end)
    local ok, err = pcall(save.write, 'vision', { 'ball', 'colour' }, 1, T)
    assert.is_false(ok)
    assert.matches("ball.colour", err)
  end)
end)

describe('param', function()
  local shm = require('shm')
  setup(function() shm.unlink('param') end)
  teardown(function() shm.unlink('param') end)

  it('refuses an unknown key, a wrong type, NaN, a list of another length, naming the key', function()
    local param = fresh_param()
    param.reset()
    local function err(f, ...)
      local ok, e = pcall(f, ...)
      assert.is_false(ok)
      return e
    end
    assert.matches("unknown key 'walk.tStepp'", err(param, 'walk.tStepp', 0.3))
    assert.matches("Config/robots/op3/walk.lua", err(param, 'walk.tStepp', 0.3))
    assert.matches("unknown key 'nosuch.x'", err(param, 'nosuch.x', 1))
    assert.matches("'walk.tStep' is a number, got string", err(param, 'walk.tStep', '0.3'))
    assert.matches("'walk.tStep' must be a finite number", err(param, 'walk.tStep', 0 / 0))
    assert.matches("'walk.tStep' must be a finite number", err(param, 'walk.tStep', math.huge))
    assert.matches("'walk.stepLimitX' is a list of 2 numbers", err(param, 'walk.stepLimitX', { 1 }))
    assert.matches("'walk.feedback' is a table", err(param, 'walk.feedback', 1))
    assert.equal(0, #param.changes())
  end)

  it('carries changes to a follower, which applies them to its Config in place and runs its hooks', function()
    local param = fresh_param()
    param.reset()
    assert.equal(0.3, param('walk.tStep', 0.3))
    param('vision.ball.max_range', 4)
    param('walk.stepLimitX', { -0.02, 0.05 })
    param('vision.publish_labels', true)
    assert.equal(3 + 1, #param.changes())
    -- another process: loads its config, then follows
    local follower_param = fresh_param()
    Config.reload()
    local walk = Config.load('walk')
    local limits = walk.stepLimitX
    local seen = {}
    local f = follower_param.follow('test', { quiet = true })
    f:on('walk', function(key, value) seen[#seen + 1] = key .. '=' .. follower_param.show(value) end)
    -- applied at follow(): only the concerns it uses (walk), not vision
    assert.equal(0.3, walk.tStep)
    assert.equal(limits, walk.stepLimitX)
    assert.same({ -0.02, 0.05 }, { limits[1], limits[2] })
    f:poll()
    -- a later change, seen at the next poll, hooks run
    param('walk.tStep', 0.32)
    f:poll()
    assert.equal(0.32, walk.tStep)
    assert.same({ 'walk.tStep=0.32' }, seen)
    local st = follower_param.status()
    assert.equal(1, #st)
    assert.equal('test', st[1].name)
    assert.is_true(st[1].applied)
    assert.matches('walk', st[1].concerns)
    f:leave()
    assert.equal(0, #follower_param.status())
  end)
end)
