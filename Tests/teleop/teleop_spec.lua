-- luacheck: std +busted
-- Teleoperation without a simulator (docs/teleoperation.md): the Hubo2+'s key poses load and bad
-- ones are refused naming the file and the key; the validator (Lib/teleop.lua) accepts "reach"
-- from the walk's stance and refuses four crafted key poses (Tests/teleop/keyposes/) each for its
-- reason at its first failing instant; the executor (the motion state teleop and its shm link, the
-- joints following the commands perfectly) starts only a trajectory that arrived whole with its
-- checksum right, pauses, resumes and stops at the tick a command arrives, and on a lost link
-- finishes the segment or holds, never starting the next.
local Config = require('Config')
local kin = require('kinematics')
local control = require('Motion.control')
local teleop = require('teleop')
local teleop_link = require('Motion.teleop_link')
local Teleop = require('Teleop')
local shm = require('shm')

local BODY = 'hubo2plus'
local FIXTURES = (os.getenv('HRP_ROOT') or '.') .. '/Tests/teleop/keyposes/'
local robot = Config.load('robot', nil, { robot = BODY })
local params = Config.load('walk', nil, { robot = BODY })
local model = kin.load({ robot = BODY })
local cfg = Config.load('teleop', nil, { robot = BODY })

local function tick(c, link, k)
  for i = 1, c.n do c.pos[i] = c.q[i] end
  link:before(c)
  c:tick(c.t + c.dt)
  link:after(c, k)
end

-- the walk's stance, reached with perfect joints: where a trajectory starts
local block = shm.open('teleop')
local link = teleop_link.new(block, shm.open('teleop.chunk'), cfg.executor.link_timeout, teleop_link.bounds(robot))
local c = control.new({ robot = robot, params = params, model = model })
local k = 0
local function run(n, beat)
  for _ = 1, n do
    k = k + 1
    if beat then Teleop.heartbeat() end
    tick(c, link, k)
  end
end
run(400)
local q0 = {}
for i = 1, c.n do q0[i] = c.q[i] end

local function kp_error(path)
  local ok, err = pcall(teleop.keypose_file, path, { robot = BODY })
  assert.is_false(ok)
  return tostring(err)
end

local function write(text)
  local path = os.tmpname() .. '.lua'
  local f = assert(io.open(path, 'w'))
  f:write(text)
  f:close()
  return path
end

describe('key poses', function()
  it("of the Hubo2+ load (reach, ready, push, crouch_reach)", function()
    for _, name in ipairs({ 'reach', 'ready', 'push', 'crouch_reach' }) do
      local kp = teleop.keypose(name, { robot = BODY })
      assert.equals(name, kp.name)
      assert.equals('hold', kp.limbs.lfoot.mode)
    end
  end)

  it('refuse bad input naming the file and the key', function()
    local cases = {
      { "limbs = { rhand = { mode = 'grab' } }", "key 'limbs.rhand.mode' must be 'free', 'hold' or 'follow'" },
      { "limbs = { rhand = { mode = 'free' } }", "key 'limbs.rhand.pos' must be 3 finite numbers" },
      { "limbs = { rhand = { mode = 'free', pos = { 0, 0, 0/0 } } }", "key 'limbs.rhand.pos' must be 3 finite" },
      { "limbs = { tail = { mode = 'hold' } }", "key 'limbs.tail' names no limb of the teleop config" },
      { "limbs = { lfoot = { mode = 'free', pos = { 0, 0.1, 0.1 } } }", "key 'limbs.lfoot.mode' must be 'hold'" },
      { "limbs = { rhand = { mode = 'hold' } }, joints = { XYZ = 1 }", "key 'joints.XYZ' names no joint" },
      { "limbs = { rhand = { mode = 'hold' } }, com = { 1 }", "key 'com' must be 2 finite numbers" },
    }
    for _, case in ipairs(cases) do
      local path = write("return { doc = 'x', duration = 2, " .. case[1] .. ' }')
      local err = kp_error(path)
      os.remove(path)
      assert.is_truthy(err:find(path, 1, true), err)
      assert.is_truthy(err:find(case[2], 1, true), err)
    end
    local path = write("return { doc = 'x', duration = 0.01, limbs = { rhand = { mode = 'hold' } } }")
    assert.is_truthy(kp_error(path):find("key 'duration' must be a number of seconds in 0.2..60", 1, true))
    os.remove(path)
  end)
end)

local v = teleop.validator({ robot = BODY })

describe('the validator', function()
  local plan
  it('accepts "reach" from the stance, every sample checked', function()
    local kp = teleop.keypose('reach', { robot = BODY })
    local why
    plan, why = v:plan(q0, { kp })
    assert.is_nil(why and why.message)
    local f = plan.figures
    print(string.format('# reach: %d samples (%.2f s), hand %.1f mm from its target, COM >= %.1f mm inside the '
      .. 'support polygon, feet drift %.2f mm, peak joint speed %.0f %% of the actuators\', %d collision pairs, '
      .. 'solve + checks %.0f ms (collision %.0f ms)', plan.n, (plan.n - 1) * plan.dt, f.reach * 1e3,
      f.com_margin * 1e3, f.foot_drift * 1e3, f.speed_share * 100, v.col:npair(), f.solve_us / 1e3,
      f.collide_us / 1e3))
    assert.is_true(f.reach <= cfg.check.reach)
    assert.is_true(f.com_margin >= cfg.check.com_margin)
    assert.equals(plan.n, plan.segments[1])
    assert.equals(1 + math.floor(kp.duration / plan.dt + 0.5), plan.n)
    for i = 1, plan.n do assert.equals(#robot.joints, #plan.q[i]) end
  end)

  it("accepts each of the Hubo2+'s key poses from the stance", function()
    for _, name in ipairs({ 'ready', 'push', 'crouch_reach' }) do
      local p, why = v:plan(q0, { teleop.keypose(name, { robot = BODY }) })
      assert.is_nil(why and why.message)
      print(string.format('# %s: %d samples, hand %.1f mm off, COM >= %.1f mm inside, peak joint speed %.0f %%', name,
        p.n, p.figures.reach * 1e3, p.figures.com_margin * 1e3, p.figures.speed_share * 100))
    end
  end)

  it('accepts a plan of two key poses (ready, then push)', function()
    local p, why = v:plan(q0, { teleop.keypose('ready', { robot = BODY }), teleop.keypose('push', { robot = BODY }) })
    assert.is_nil(why and why.message)
    assert.equals(2, #p.segments)
    print(string.format('# ready + push: %d samples, hand %.1f mm off, COM >= %.1f mm inside', p.n,
      p.figures.reach * 1e3, p.figures.com_margin * 1e3))
  end)

  local bad = {
    { 'out_of_reach', 'reach' },
    { 'self_collision', 'self_collision' },
    { 'com_outside', 'com' },
    { 'joint_limit', 'joint_limit' },
  }
  for _, case in ipairs(bad) do
    it(string.format('refuses %s for %s, naming the first failing instant', case[1], case[2]), function()
      local kp = teleop.keypose_file(FIXTURES .. case[1] .. '.lua', { robot = BODY })
      local p, why = v:plan(q0, { kp })
      assert.is_nil(p)
      print('# ' .. why.message)
      assert.equals(case[2], why.reason, why.message)
      assert.equals(case[1], why.keypose)
      assert.is_true(why.sample > 1 and why.sample <= 1 + math.floor(kp.duration / v.dt + 0.5))
      assert.near(why.t, (why.sample - 1) * v.dt, 1e-9)
    end)
  end

  it('has a checksum that changes with any one angle', function()
    local h = teleop.checksum(plan.q, plan.n, plan.nj)
    assert.equals(plan.checksum, h)
    local keep = plan.q[plan.n][5]
    plan.q[plan.n][5] = keep + 1e-12
    assert.are_not.equal(h, teleop.checksum(plan.q, plan.n, plan.nj))
    plan.q[plan.n][5] = keep
  end)
end)

describe('the executor', function()
  local kp = teleop.keypose('reach', { robot = BODY })
  local plan = assert(v:plan(q0, { kp }))
  local function wait() run(1, true) end

  local function status() return Teleop.status() end

  it('refuses a start before the trajectory arrived, and one whose checksum is wrong', function()
    c:request('teleop')
    run(300, true)
    assert.equals('teleop', c:state())
    Teleop.start(999)
    run(1, true)
    assert.equals('idle', status().state)
    assert.is_false(status().last.ok)
    assert.is_truthy(status().reason:find('has not arrived'))
    local id = Teleop.send(plan, wait, { corrupt = 2 })
    run(1, true)
    assert.is_truthy(status().reason:find('checksum'), status().reason)
    Teleop.start(id)
    run(1, true)
    assert.is_false(status().last.ok)
    assert.is_truthy(status().reason:find('checksum'), status().reason)
    assert.equals('idle', status().state)
  end)

  it('refuses a trajectory with a sample beyond a limit or a step too fast, whoever sent it', function()
    local function copy_plan()
      local q = {}
      for i = 1, plan.n do
        q[i] = {}
        for j = 1, plan.nj do q[i][j] = plan.q[i][j] end
      end
      return { q = q, n = plan.n, nj = plan.nj, segments = { plan.n } }
    end
    local far = copy_plan()
    for i = 200, far.n do far.q[i][14] = 3.0 end   -- RWY beyond 2.967 from sample 200
    far.checksum = teleop.checksum(far.q, far.n, far.nj)
    Teleop.send(far, wait)
    run(1, true)
    assert.is_truthy(status().reason:find('sample 200, RWY at 3.000 rad beyond', 1, true), status().reason)
    assert.equals('idle', status().state)
    local jump = copy_plan()
    for i = 300, jump.n do jump.q[i][4] = jump.q[i][4] + 0.1 end   -- LSP jumps 0.1 rad at sample 300
    jump.checksum = teleop.checksum(jump.q, jump.n, jump.nj)
    Teleop.send(jump, wait)
    run(1, true)
    assert.is_truthy(status().reason:find('sample 300, LSP steps', 1, true), status().reason)
    assert.equals('idle', status().state)
  end)

  it('plays a whole trajectory; pause, resume and stop act at the tick they arrive', function()
    for i = 1, c.n do c.q[i] = q0[i] end
    local id = Teleop.send(plan, wait)
    run(1, true)
    assert.equals('ready', status().state)
    assert.equals(id, status().loaded)
    Teleop.start(id)
    run(40, true)
    -- the garbage the executor and its link make per tick while playing, over 400 ticks (the
    -- heartbeat bumped in place: the sender's writes are not the motion process's)
    collectgarbage('collect')
    collectgarbage('stop')
    local k0 = collectgarbage('count')
    for _ = 1, 400 do
      block.heartbeat[0] = block.heartbeat[0] + 1
      k = k + 1
      tick(c, link, k)
    end
    local per = (collectgarbage('count') - k0) * 1024 / 400
    collectgarbage('restart')
    print(string.format('# executor playing: %.1f bytes of garbage per tick (400 ticks)', per))
    assert.is_true(per < 16, string.format('%.1f bytes per tick', per))
    run(10, true)
    assert.equals('running', status().state)
    assert.equals(450, status().sample)
    Teleop.pause()
    run(1, true)
    local held = {}
    for i = 1, c.n do held[i] = c.q[i] end
    run(50, true)
    assert.equals('paused', status().state)
    for i = 1, c.n do assert.equals(held[i], c.q[i]) end
    Teleop.resume()
    run(10, true)
    assert.equals(460, status().sample)
    Teleop.stop()
    run(1, true)
    assert.equals('stopped', status().state)
    for i = 1, c.n do assert.equals(plan.q[460][i], c.q[i]) end
    run(20, true)
    for i = 1, c.n do assert.equals(plan.q[460][i], c.q[i]) end
    Teleop.resume()
    run(1, true)
    assert.is_false(status().last.ok)
  end)

  it('on a lost link finishes the segment and never starts the next (on_lost = finish)', function()
    -- back to the start through the plan's first sample, then a two-segment plan
    for i = 1, c.n do c.q[i] = q0[i] end
    run(1, true)
    local two = assert(v:plan(q0, { kp, teleop.keypose('ready', { robot = BODY }) }))
    local id = Teleop.send(two, wait)
    Teleop.start(id)
    run(50, true)
    assert.equals('running', status().state)
    run(two.segments[1] + 100, false)   -- the heartbeat stops
    local s = status()
    assert.is_false(s.link_ok)
    assert.equals('held', s.state)
    assert.equals(two.segments[1], s.sample)
    print('# lost link: ' .. s.reason)
    for i = 1, c.n do assert.equals(two.q[two.segments[1]][i], c.q[i]) end
    Teleop.resume()
    run(1, false)
    assert.is_false(status().last.ok)
  end)

  it('on a lost link holds at once with on_lost = hold, and starts nothing without a link', function()
    for i = 1, c.n do c.q[i] = q0[i] end
    run(1, true)
    local id = Teleop.send(plan, wait)
    local on_lost = cfg.executor.on_lost
    c.teleop_cfg.on_lost = 'hold'
    Teleop.start(id)
    run(40, true)
    run(200, false)
    local s = status()
    local lost_at = 40 + math.floor(cfg.executor.link_timeout / c.dt)
    assert.equals('held', s.state)
    assert.is_true(math.abs(s.sample - lost_at) <= 2, tostring(s.sample))
    c.teleop_cfg.on_lost = on_lost
    Teleop.stop()
    run(1, false)
    for i = 1, c.n do c.q[i] = q0[i] end
    Teleop.start(id)
    run(1, false)
    assert.is_false(status().last.ok)
    assert.is_truthy(status().reason:find('link is lost'))
  end)
end)
