-- luacheck: std +busted
-- The touch motion (Player/Motion/states/touch.lua) on the HOAP-3's controller without a robot: a
-- "wall" that pushes back on the left wrist in proportion to how far the shoulder passed the angle
-- where the hand meets it; the right arm meets nothing.
local Config = require('Config')
local kin = require('kinematics')
local control = require('Motion.control')
local Motion = require('Motion')

local NAME = 'hoap3'
local robot = Config.export('robot', { robot = NAME })
local params = Config.export('walk', { robot = NAME })
local cfg = Config.load('touch', nil, { robot = NAME })
local model = assert(kin.new(robot, Config.robot_file(robot.description, NAME), NAME))

local function index(name)
  for i, j in ipairs(robot.joints) do if j == name then return i end end
end
local L_SHO, R_SHO = index('l_sho_pitch'), index('r_sho_pitch')
local WALL_AT, WALL_STIFFNESS = 0.6, 20   -- rad of l_sho_pitch where the hand meets it; N per rad past it

local function run(c, seconds, each)
  local dt = robot.period
  for _ = 1, math.floor(seconds / dt + 0.5) do
    for i = 1, c.n do c.pos[i] = c.q[i] end
    -- the left wrist's sensor (dcm.sensor.ft's third six) feels the wall, plus the hand's weight
    local push = math.max(0, WALL_AT - c.q[L_SHO]) * WALL_STIFFNESS
    c.ft[13], c.ft[14], c.ft[15] = push, 0, 0.2
    c.ft[19], c.ft[20], c.ft[21] = 0, 0, 0.2
    c:tick(c.t + dt)
    if each then each(c) end
  end
end

describe('touch', function()
  it('stops each arm on its own wrist force and presses with `press`, the other arm goes on to its pose', function()
    local c = control.new({ robot = robot, params = params, model = model })
    c.t0 = 0
    run(c, 1.5)
    assert.equals('stance', c:state())
    c:request('touch')
    local deepest = math.huge
    run(c, 10, function(x) deepest = math.min(deepest, x.q[L_SHO]) end)
    assert.equals('touch', c:state())
    local report = c.machine.modules.touch.report(c)
    assert.is_true(report[1].touched, 'the left arm touched')
    assert.is_false(report[2].touched, 'the right arm touched nothing')
    assert.equals(1, report[2].progress)
    assert.near(cfg.arms[2].to.r_sho_pitch, c.q[R_SHO], 1e-9)
    -- held against the wall at `press`: the shoulder where the wall pushes back with it
    local press_at = WALL_AT - cfg.press / WALL_STIFFNESS
    assert.near(press_at, c.q[L_SHO], 0.01)
    assert.is_true(deepest > press_at - 0.05, 'the arm never drove far into the wall: ' .. deepest)
    -- another request leaves through stance
    c:request('stand')
    run(c, 2)
    assert.equals('stance', c:state())
  end)

  it('is refused for a body that lists no arms, naming it', function()
    assert.equals(0, #Config.load('touch', nil, { robot = 'op3' }).arms)
    local old = os.getenv('ROBOT')
    if old == nil or old == 'op3' then
      local ok, err = pcall(Motion.request, 'touch')
      assert.is_false(ok)
      assert.truthy(tostring(err):find("the body 'op3' has no arms to touch with", 1, true), err)
    end
  end)
end)
