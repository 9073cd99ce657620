-- luacheck: std +busted
-- Motion and Walk APIs over the motion shm block, without a motion process.
local shm = require('shm')
local Motion = require('Motion')
local Walk = require('Walk')
local Config = require('Config')

local params = Config.load('walk')
local motion = shm.open('motion')

describe('Motion API', function()

  it('writes requests as state indices and bumps the sequence', function()
    local seq = motion.request_seq[0]
    assert.is_true(Motion.request('walk'))
    assert.equals(seq + 1, motion.request_seq[0])
    assert.equals('walk', Motion.requested())
    Motion.request('stand')
    assert.equals('stance', Motion.requested())
    Motion.request('kick_right')
    assert.equals('kick_right', Motion.requested())
  end)

  it('refuses unknown motion names', function()
    assert.has_error(function() Motion.request('dance') end)
  end)

  it('names the state the motion process publishes', function()
    motion.state[0] = 7
    assert.equals('standup_front', Motion.state())
    motion.state[0] = 2
    assert.equals('stance', Motion.state())
  end)
end)

describe('Walk API', function()
  teardown(function() shm.unlink('motion') end)

  it('clamps velocity commands to the limits of the walk config', function()
    local vx, vy, va = Walk.set_velocity(5, 0, 0)
    assert.is_near(params.velLimitX[2], vx, 1e-12)
    assert.equals(0, vy)
    assert.equals(0, va)
    assert.is_near(params.velLimitX[2], motion.velocity[0], 1e-12)
    Walk.set_velocity(0, 0, -10)
    assert.is_near(params.velLimitA[1], motion.velocity[2], 1e-12)
  end)

  it('refuses NaN and infinite commands and keeps the last good one', function()
    Walk.set_velocity(0.1, 0, 0)
    local ok, err = Walk.set_velocity(0 / 0, 0, 0)
    assert.is_nil(ok)
    assert.matches('refused', err)
    ok = Walk.set_velocity(0, math.huge, 0)
    assert.is_nil(ok)
    assert.is_near(0.1, motion.velocity[0], 1e-12)
  end)

  it('checks parameter changes before sending them', function()
    assert.has_error(function() Walk.set('noSuchParameter', 1) end)
    assert.has_error(function() Walk.set('tStep', 0 / 0) end)
    assert.has_error(function() Walk.set('velLimitX', { 1 }) end)
    motion.pid[0] = 0
    local seq = motion.param_seq[0]
    assert.is_true(Walk.set('feedback.ankle', { 0.2, 0.1 }))
    assert.equals(seq + 1, motion.param_seq[0])
    assert.equals(2, motion.param_count[0])
    assert.equals('pending', Walk.param_status())
  end)
end)
