-- luacheck: std +busted
-- The walk config's spec (Config/spec/walk.lua), checked where the config is loaded: every body's
-- walk passes, the kick phases and the arms get the fields they leave out, and a bad value fails
-- naming the file that set it and the key (a body's walk.lua over the real defaults, in a tree of
-- the test's own).
local Config = require('Config')
local native = require('native')
local files = require('Tests.files')

local root = native.root()
local tmp

-- the error of loading the walk of a body whose walk.lua is `text` (nil: it loads)
local n = 0
local function load_error(text)
  n = n + 1
  local body = 'bot' .. n
  files.write(tmp, 'Config/robots/' .. body .. '/walk.lua', text)
  local ok, err = pcall(Config.load, 'walk', nil, { robot = body, platform = 'Test' })
  if ok then return nil end
  return err, 'Config/robots/' .. body .. '/walk.lua'
end

local function fails(text, msg)
  local err, file = load_error(text)
  assert.is_string(err, 'loads: ' .. text)
  assert.equal(file .. ': ' .. msg, err)
end

describe('walk config spec', function()
  files.config_root(function(dir)
    tmp = dir
    for _, f in ipairs({ 'Config/common/walk.lua', 'Config/spec/walk.lua' }) do
      files.write(tmp, f, files.read(root .. '/' .. f))
    end
    files.write(tmp, 'Config/platforms/Test/walk.lua', 'return {}')
  end)

  it("passes every body's walk, filling the kick phases' and the arms' left-out fields", function()
    Config.use_root(nil)
    for _, body in ipairs({ 'op3', 'darwin', 'hubo2plus', 'waistbot', 'hoap3' }) do
      local w = Config.load('walk', nil, { robot = body, platform = 'Sim' })
      for _, ph in ipairs(w.kick.leg) do
        assert.is_number(ph.x + ph.y + ph.z + ph.hip + ph.knee + ph.ankle + ph.arm)
      end
      for _, ph in ipairs(w.kick.body) do assert.is_number(ph.shift + ph.lean + ph.height + ph.tilt + ph.arms) end
      for _, a in pairs(w.arms) do assert.is_not_nil(a.pitch) assert.is_not_nil(a.roll) end
    end
    local wk = Config.load('walk', nil, { robot = 'op3', platform = 'Sim' }).walkKick
    assert.equal(0, wk.forward.phases[1].y)
    assert.equal(0, wk.side.phases[1].hipRoll)
    Config.use_root(tmp)
  end)

  it('fills an absent ballMax with false and a phase field with 0', function()
    assert.is_nil(load_error([[return { walkKick = { forward = { phases = { { duration = 0.1, x = 0.01 } } } } }]]))
    local w = Config.load('walk', nil, { robot = 'bot' .. n, platform = 'Test' })
    assert.is_false(w.walkKick.forward.ballMax)
    assert.same({ duration = 0.1, x = 0.01, y = 0, z = 0, hip = 0, knee = 0, ankle = 0, hipRoll = 0, tilt = 0,
      arms = 0, arm = 0 }, Config.export('walk', { robot = 'bot' .. n, platform = 'Test' }).walkKick.forward.phases[1])
  end)

  it('names the file and the key of a wrong type', function()
    fails('return { turnToeIn = "half" }', "key 'turnToeIn' must be a number, got string")
    fails('return { turnStep = 0.3 }',
      "key 'turnStep' must be false or { tStep = s > 0, va = { lo, hi } } rad/s with 0 <= lo < hi")
    fails('return { walkKick = 2 }', "key 'walkKick' must be false or a table (expire, maxSpeed, forward, side)")
  end)

  it('names the file and the key of a value out of range', function()
    fails('return { turnToeIn = 2 }', "key 'turnToeIn' must be a number in 0..1, got 2")
    fails('return { hipYawLead = -0.1 }', "key 'hipYawLead' must be a number >= 0, got -0.1")
    fails('return { balance = { leakTime = 0 } }', "key 'balance.leakTime' must be a number > 0, got 0")
    fails('return { balance = { minForce = -1 } }', "key 'balance.minForce' must be a number >= 0, got -1")
    fails('return { kick = { leg = { { duration = 0.1 }, { duration = 0 } } } }',
      "key 'kick.leg.2.duration' must be a number > 0, got 0")
    fails([[return { walkKick = { side = { ballMax = 1 / 0, phases = { { duration = 0.1 } } } } }]],
      "key 'walkKick.side.ballMax' must be false or a number (m), got inf")
  end)

  it('names the file and the key of a bad pair', function()
    fails('return { balance = { walkGain = { 1 } } }', "key 'balance.walkGain' must be { x, y }, numbers >= 0")
    fails('return { balance = { zmpGain = { 1, -1 } } }', "key 'balance.zmpGain' must be { x, y }, numbers >= 0")
    fails('return { turnStep = { tStep = 0.2, va = { 2, 1 } } }',
      "key 'turnStep' must be false or { tStep = s > 0, va = { lo, hi } } rad/s with 0 <= lo < hi")
  end)

  it('names the file and the key of an unknown name', function()
    fails('return { engine = "fast" }', "key 'engine' must be 'analytic' or 'preview', got 'fast'")
    fails('return { arms = { x = { posture = {} } } }', "key 'arms.x' must have the sides 'l' and 'r' only")
    fails('return { arms = { l = { posture = { l_el = 0 }, pitch = "l_sho_pitch" } } }',
      "key 'arms.l.pitch' must name a joint of 'arms.l.posture' or be false, got 'l_sho_pitch'")
    fails('return { arms = { l = { posture = { l_el = 0 }, yaw = "l_el" } } }',
      "key 'arms.l.yaw' is not a key of an arm (posture, pitch, roll)")
    fails('return { kick = { body = { { duration = 0.1, shfit = 1 } } } }',
      "key 'kick.body.1.shfit' is not a field of a phase (duration, shift, lean, height, tilt, arms)")
    fails([[return { walkKick = { forward = { phases = { { duration = 0.1, x = 'far' } } } } }]],
      "key 'walkKick.forward.phases.1.x' must be a finite number, got 'far'")
  end)

  it('names a key set by the platform layer with its file', function()
    files.write(tmp, 'Config/platforms/Odd/walk.lua', 'return { hipYawLead = -1 }')
    files.write(tmp, 'Config/robots/plain/walk.lua', 'return {}')
    assert.has_error(function() Config.load('walk', nil, { robot = 'plain', platform = 'Odd' }) end,
      "Config/platforms/Odd/walk.lua: key 'hipYawLead' must be a number >= 0, got -1")
  end)
end)
