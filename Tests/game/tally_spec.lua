-- luacheck: std +busted
-- The referee's per-robot tally (Tools/match/tally.lua): seconds per role only while PLAYING and
-- not penalized, a mirrored belief in either team's frame, falls and penalties counted once each.
local tally = require('Tools.match.tally')

describe('referee tally', function()
  it('tells a mirrored belief from a right or merely inaccurate one', function()
    assert.is_true(tally.mirrored(-3.0, 1.0, 3.0, -1.0))     -- the mirror of the truth
    assert.is_false(tally.mirrored(3.1, -0.9, 3.0, -1.0))    -- right
    assert.is_false(tally.mirrored(0.3, 0.2, -0.4, -0.1))    -- near the centre: nothing said
    assert.is_false(tally.mirrored(1.0, -3.0, 3.0, -1.0))    -- wrong, but not the mirror
  end)

  it('counts role seconds, mirrored seconds (team frame turned by the side), falls and penalties', function()
    local t = tally.new({ { team = 1, player = 1 }, { team = 2, player = 1 } }, 0.3)
    local truth = { x = 3.0, y = -1.0, roll = 0, pitch = 0, fallen = false }
    -- team 2 defends +x (side -1): its belief (-3, 1) in its own frame is (3, -1) on the field: right
    t:look(0.5, true, 2, truth, { x = -3.0, y = 1.0, role = 4 }, -1, false)
    -- team 1 (side 1) believes (-3, 1): the mirror
    t:look(0.5, true, 1, truth, { x = -3.0, y = 1.0, role = 1 }, 1, false)
    t:look(0.5, false, 1, truth, { x = -3.0, y = 1.0, role = 1 }, 1, false)      -- not playing
    t:look(0.5, true, 1, { x = 3, y = -1, roll = 0, pitch = 1.2, fallen = true }, { x = 3, y = -1, role = 2 }, 1, false)
    t:look(0.5, true, 1, { x = 3, y = -1, roll = 0, pitch = 1.2, fallen = true }, { x = 3, y = -1, role = 2 }, 1, true)
    t:look(0.5, true, 1, { x = 3, y = -1, roll = 0, pitch = 1.2, fallen = true }, { x = 3, y = -1, role = 2 }, 1, true)
    -- rolling on the ground: the flag off for a look, the torso still tilted, then on again: the same fall
    t:look(0.5, true, 1, { x = 3, y = -1, roll = 0, pitch = 0.9, fallen = false }, { x = 3, y = -1, role = 2 }, 1, true)
    t:look(0.5, true, 1, { x = 3, y = -1, roll = 0, pitch = 1.2, fallen = true }, { x = 3, y = -1, role = 2 }, 1, true)
    local r1, r2 = t.robots[1], t.robots[2]
    assert.are.equal(0.5, r2.role.goalkeeper)
    assert.are.equal(0, r2.mirrored)
    assert.are.equal(0.5, r1.role.striker)
    assert.are.equal(0.5, r1.role.supporter)
    assert.are.equal(0.5, r1.mirrored)
    assert.are.equal(1, r1.falls)
    assert.are.equal(1, r1.penalties)
    assert.matches('^tally 1/1 striker=0.5 supporter=0.5 defender=0.0 goalkeeper=0.0 mirrored=0.5 falls=1 penalties=1$',
      t:lines()[1])
  end)
end)
