-- luacheck: std +busted
-- Lib/fsm.lua: states as modules with entry/update/exit, transitions declared in one place.
local fsm = require('fsm')

local function recorder(log, name, script)
  return {
    entry = function() log[#log + 1] = 'entry:' .. name end,
    update = function(ctx) log[#log + 1] = 'update:' .. name return script and script(ctx) end,
    exit = function() log[#log + 1] = 'exit:' .. name end,
  }
end

describe('fsm', function()
  it('enters the initial state, follows returned events and runs exit before entry', function()
    local log = {}
    local mods = {
      a = recorder(log, 'a', function(ctx) if ctx.go then return 'go' end end),
      b = recorder(log, 'b'),
    }
    local m = fsm.new({ name = 't', states = { 'a', 'b' }, load = function(n) return mods[n] end,
      transitions = { a = { go = 'b' } } })
    m:update({ t = 0 })
    assert.are.equal('a', m:state())
    assert.are.equal(0, m:index())
    m:update({ t = 1, go = true })
    assert.are.equal('b', m:state())
    assert.are.equal(1, m:index())
    assert.are.same({ 'entry:a', 'update:a', 'update:a', 'exit:a', 'entry:b' }, log)
    assert.are.equal(0.5, m:since(1.5))
  end)

  it('takes wildcard transitions and counts events nobody handles', function()
    local mods = { a = {}, b = {}, c = {} }
    local m = fsm.new({ name = 't', states = { 'a', 'b', 'c' }, load = function(n) return mods[n] end,
      transitions = { a = { x = 'b' }, ['*'] = { stop = 'c', x = 'a' } } })
    assert.is_true(m:event('x', { t = 0 }))
    assert.are.equal('b', m:state())
    assert.is_true(m:event('x', { t = 0 })) -- b has no x of its own: the wildcard's
    assert.are.equal('a', m:state())
    assert.is_false(m:event('nonsense', { t = 0 }))
    assert.are.equal(1, m.unhandled.nonsense)
    assert.is_true(m:event('stop', { t = 0 }))
    assert.are.equal('c', m:state())
  end)

  it('rejects declarations naming unknown states or failing modules', function()
    local ok_mod = function() return {} end
    assert.has_error(function()
      fsm.new({ name = 'bad', states = { 'a' }, load = ok_mod, transitions = { a = { e = 'zz' } } })
    end, "fsm 'bad': event 'e' from 'a' names unknown state 'zz'")
    assert.has_error(function()
      fsm.new({ name = 'bad', states = { 'a' }, load = ok_mod, initial = 'q' })
    end, "fsm 'bad': initial names unknown state 'q'")
    assert.has_error(function()
      fsm.new({ name = 'bad', states = { 'a' }, load = function() error('boom', 0) end })
    end, "fsm 'bad': state 'a' did not load: boom")
  end)

  it('loads every declared state of the real machines', function()
    for _, which in ipairs({ 'BodyFSM', 'HeadFSM' }) do
      local def = require(which .. '.machine')
      local m = fsm.new({ name = which, states = def.states, transitions = def.transitions,
        initial = def.initial, load = function(n) return require(which .. '.' .. n) end })
      assert.are.equal(def.initial, m:state())
    end
  end)
end)
