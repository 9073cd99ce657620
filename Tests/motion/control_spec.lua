-- luacheck: std +busted
-- The motion controller without a robot: the state machine's paths, fall detection from the IMU,
-- requests (keyframe files: keyframe_spec.lua; who drives which joint: ownership_spec.lua).
local Config = require('Config')
local kin = require('kinematics')
local control = require('Motion.control')
local keyframe = require('Motion.keyframe')

local robot = Config.load('robot')
local params = Config.load('walk')
local model = kin.load()

-- a controller whose "robot" tracks the commands perfectly and stands upright
local function make(initial)
  local c = control.new({ robot = robot, params = params, model = model, initial = initial })
  c.t0 = 0
  return c
end
local function run(c, seconds, imu)
  local dt = robot.period
  for _ = 1, math.floor(seconds / dt + 0.5) do
    for i = 1, c.n do c.pos[i] = c.q[i] end
    if imu then imu(c) end
    c:tick(c.t + dt)
    for i = 1, c.n do assert(c.q[i] == c.q[i], 'NaN command') end
  end
end

describe('motion controller', function()
  it('starts in stance and walks when asked, then stops into stance', function()
    local c = make()
    run(c, 1.5)
    assert.equals('stance', c:state())
    c:request('walk')
    c.vel_cmd[1] = 0.2
    run(c, 0.1)
    assert.equals('walk', c:state())
    run(c, 3)
    assert.is_true(c.walk.uTorso[1] > 0.3, 'walked ' .. c.walk.uTorso[1])
    c:request('stand')
    run(c, 2)
    assert.equals('stance', c:state())
    assert.is_false(c.walk:is_active())
  end)

  it('kicks from stance and from walking, then stands', function()
    local c = make()
    run(c, 1.2)
    c:request('kick_left')
    run(c, 0.1)
    assert.equals('kick_left', c:state())
    run(c, 3)
    assert.equals('stance', c:state())
    c:request('walk')
    run(c, 1)
    c:request('kick_right')
    local seen = false
    for _ = 1, 400 do
      run(c, 0.008)
      if c:state() == 'kick_right' then seen = true end
    end
    assert.is_true(seen)
    assert.equals('stance', c:state())
  end)

  it('relaxes at once from anywhere and sits through keyframes', function()
    local c = make()
    run(c, 1.2)
    c:request('walk')
    run(c, 0.5)
    c:request('relax')
    assert.equals('relax', c:state())
    run(c, 0.1)
    for i = 1, c.n do assert.equals(0, c.h[i]) end
    c:request('sit')
    run(c, 0.1)
    assert.equals('sit', c:state())
    run(c, 2)
    assert.equals('sit', c:state())
    assert.is_near(0.3, c.h[c.ji.l_knee], 1e-9)
  end)

  it('detects a fall from the IMU, goes soft and stands up from the front', function()
    local c = make()
    run(c, 1.2)
    c:request('walk')
    run(c, 0.5)
    local pitch = 0
    -- tipping forwards, then lying still on the front; upright again once the stand-up ends
    run(c, 1.0, function(s)
      if s:state() == 'walk' or s:state() == 'falling' then pitch = math.min(1.5, pitch + 0.02) end
      s.angle[2] = pitch
      s.gyro[2] = pitch < 1.5 and 2.5 or 0
    end)
    assert.equals(1, c.falls)
    assert.equals('falling', c:state())
    assert.is_true(c.h[c.ji.l_knee] <= params.fallHardness + 1e-9)
    run(c, 1.5, function(s) s.angle[2], s.gyro[2], s.acc[1], s.acc[3] = 1.5, 0, -9.81, 0 end)
    assert.equals('standup_front', c:state())
    local d = keyframe.duration(c.keyframes.standup_front)
    run(c, d + 0.1, function(s) s.angle[2], s.gyro[2] = params.bodyTilt, 0 end)
    -- stands, and since walking was asked for, walks again
    run(c, params.tStance + 0.3)
    assert.equals('walk', c:state())
  end)

  it('ignores unknown requests', function()
    local c = make()
    assert.is_false(c:request('dance'))
    assert.equals('stand', c.want)
  end)
end)
