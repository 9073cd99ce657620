-- luacheck: std +busted
-- Run/hang.lua: which process the manager judges hung, on the robot clock.
local hang = require('Run.hang')

describe('hang watch', function()
  local p, i
  local function watch()
    p, i = 0, 0
    return hang.new(2.0, { motion = { progress = function() return p end, input = function() return i end } }, 5.0)
  end

  it('reports a process whose input moves on while its progress stands still for `after` s', function()
    local w = watch()
    w:started('motion', 10)
    p, i = 1, 1
    assert.is_nil(w:check(10.1))        -- first progress: past the start-up grace
    i = 2
    assert.is_nil(w:check(12.0))
    local name, stalled = w:check(12.2)
    assert.equal('motion', name)
    assert.is_true(stalled > 2.0 and stalled < 2.2)
    assert.is_nil(w:check(20))          -- reported once until it is started again
  end)

  it('does not judge a process without input (no camera frames) or a clock that stands', function()
    local w = watch()
    w:started('motion', 0)
    p = 1
    assert.is_nil(w:check(0.1))
    assert.is_nil(w:check(100))         -- input never moved
    w:started('motion', 100)
    p, i = 2, 2
    assert.is_nil(w:check(100))
    i = 3
    assert.is_nil(w:check(101.9))       -- the clock stands still (lockstep with a stopped participant)
  end)

  it('gives a fresh process the start-up time before its first progress', function()
    local w = watch()
    w:started('motion', 0)
    i = 5
    assert.is_nil(w:check(4.9))
    assert.equal('motion', (w:check(5.1)))
  end)

  it('restarts counting when the clock goes back (a new world)', function()
    local w = watch()
    w:started('motion', 50)
    p, i = 1, 1
    assert.is_nil(w:check(50.1))
    assert.is_nil(w:check(3))
    i = 2
    assert.is_nil(w:check(4.9))
    assert.equal('motion', (w:check(5.1)))
  end)

  it('refuses a probe without progress() or input()', function()
    assert.has_error(function() hang.new(1, { x = { progress = function() end } }) end,
      'hang.new: probe x needs progress() and input()')
  end)
end)
