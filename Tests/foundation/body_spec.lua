-- luacheck: std +busted
-- Body: joints by name and index, groups, clamping and NaN refusal before the actuator block.
local Body = require('Body')
local shm = require('shm')

describe('Body', function()
  local act = shm.open('dcm.actuator')
  local stats = shm.open('body.stats')

  before_each(function()
    act:set('command', 0)
    stats:set('clamped', 0)
    stats:set('refused', 0)
  end)

  it('names the 20 joints in order and looks them up by name or index', function()
    local names = Body.joint_names()
    assert.equal(20, #names)
    assert.equal('head_pan', names[1])
    assert.equal(Body.index('l_knee'), 9)
    assert.has_error(function() Body.set_command('no_such_joint', 0) end)
    assert.has_error(function() Body.set_command(21, 0) end)
  end)

  it('writes commands in radians to dcm.actuator', function()
    assert.is_true(Body.set_command('l_knee', 0.5))
    assert.equal(0.5, act.command[Body.index('l_knee') - 1])
    assert.equal(0.5, Body.get_command(9))
    Body.set_head_command({ 0.1, -0.2 })
    local h = Body.get_head_command()
    assert.same({ 0.1, -0.2 }, h)
  end)

  it('clamps a command beyond a joint limit and counts it', function()
    local lo, hi = Body.limits('head_pan')
    Body.set_command('head_pan', hi + 1)
    assert.equal(hi, Body.get_command('head_pan'))
    Body.set_command('head_pan', lo - 1)
    assert.equal(lo, Body.get_command('head_pan'))
    assert.equal(2, stats.clamped[0])
  end)

  it('refuses NaN and infinite commands, which never reach the actuator block', function()
    Body.set_command('l_hip_pitch', 0.3)
    for _, bad in ipairs({ 0 / 0, math.huge, -math.huge }) do
      assert.is_false(Body.set_command('l_hip_pitch', bad))
    end
    assert.is_false(Body.set_lleg_command({ 0.1, 0 / 0 }))
    assert.equal(0.3, act.command[Body.index('l_hip_pitch') - 1])
    assert.equal(0, act.command[Body.index('l_hip_roll') - 1])
    assert.equal(0.1, act.command[Body.index('l_hip_yaw') - 1])   -- the good value of the group lands
    assert.equal(4, stats.refused[0])
    assert.is_false(Body.set_hardness('l_knee', 0 / 0))
  end)

  it('reads sensors from dcm.sensor', function()
    local s = shm.open('dcm.sensor')
    s:set('gyro', { 0.1, 0.2, 0.3 })
    s:set('time', 12.5)
    s:set('position', 0)
    s.position[Body.index('head_tilt') - 1] = -0.4
    assert.same({ 0.1, 0.2, 0.3 }, Body.get_gyro())
    assert.equal(12.5, Body.get_time())
    assert.equal(-0.4, Body.get_position('head_tilt'))
    assert.same({ 0, -0.4 }, Body.get_head_position())
  end)
end)
