-- luacheck: std +busted
-- Who drives which joint (Player/Motion/control.lua): every tick starts from the hold pose, each
-- state writes only the joints it owns, a joint no state owns holds and follows outside commands,
-- a joint a caller took gets the caller's command. Run on the waistbot test body (the OP3 with a
-- waist yaw that carries the arms and head, a wrist per arm, the bus order legs first and the waist
-- last) and on the OP3 with another bus order or no arms in the walk config.
local Config = require('Config')
local kin = require('kinematics')
local control = require('Motion.control')

-- A controller on a body. opts: waist (the waistbot, whose waist no state owns), wrist (the
-- waistbot too: its wrists are extra arm joints), reorder (the body's joints in another bus order),
-- arms (the walk config's arms).
local function fake(opts)
  local name = (opts.waist or opts.wrist) and 'waistbot' or 'op3'
  -- Config.export gives a fresh plain table on every call: ours to change
  local robot = Config.export('robot', { robot = name })
  local params = Config.export('walk', { robot = name })
  if opts.reorder then
    -- group by group in another order than the tree's
    local r = {}
    for _, g in ipairs({ 'rleg', 'waist', 'larm', 'head', 'lleg', 'rarm' }) do
      for _, j in ipairs(robot.groups[g] or {}) do r[#r + 1] = j end
    end
    assert(#r == #robot.joints)
    robot.joints = r
  end
  if opts.arms then params.arms = opts.arms end
  local model = assert(kin.new(robot, Config.robot_file(robot.description, name), name))
  local c = control.new({ robot = robot, params = params, model = model })
  return c, robot, params
end

-- Runs c for `seconds`: the "robot" tracks the commands perfectly and stands upright; checks that no
-- command is NaN and that every joint the controller does not write keeps its command.
local function run(c, seconds, imu)
  local dt = c.robot.period
  for _ = 1, math.floor(seconds / dt + 0.5) do
    for i = 1, c.n do c.pos[i] = c.q[i] end
    if imu then imu(c) end
    local before = {}
    for i = 1, c.n do before[i] = c.q[i] end
    c:tick(c.t + dt)
    for i = 1, c.n do
      assert(c.q[i] == c.q[i], 'NaN command for ' .. c.robot.joints[i])
      if not c.write[i] then assert(c.q[i] == before[i], c.robot.joints[i] .. ' moved while held') end
    end
  end
end

-- stance, walk, kick both feet, walk, stand: returns the distance walked
local function exercise(c)
  run(c, 1.5)
  assert.equals('stance', c:state())
  c:request('walk')
  c.vel_cmd[1] = 0.2
  run(c, 3)
  assert.equals('walk', c:state())
  local walked = c.walk.uTorso[1]
  c:request('kick_left')
  run(c, 4)
  assert.equals('stance', c:state())
  c:request('kick_right')
  run(c, 4)
  c:request('stand')
  run(c, 1)
  assert.equals('stance', c:state())
  return walked
end

describe('motion on a body with a joint no state owns (a waist yaw)', function()
  it('stands, walks and kicks with the waist held where it was commanded', function()
    local c = fake({ waist = true })
    local w = c.ji.waist_yaw
    assert.equals(#c.robot.joints, w) -- the waistbot's bus: legs first, the waist last
    c.q[w], c.h[w] = 0.3, 1 -- the hold pose when motion starts: what the actuators hold
    local walked = exercise(c)
    assert.is_true(walked > 0.3, 'walked ' .. walked)
    assert.equals(0.3, c.q[w])
    assert.equals(0, c.owner[w])
    assert.is_false(c.write[w])
    assert.equals(1, c.owner[c.ji.l_knee])
  end)

  it('lets the hold follow an outside command (the actuator block) and stiffens it after relax', function()
    local c, robot, params = fake({ waist = true })
    local w = c.ji.waist_yaw
    run(c, 1)
    -- a tool writes the waist's command: the hold pose follows it (Player/Motion/main.lua syncs)
    local cmd, hard, taken, taken_cmd = {}, {}, {}, {}
    for i = 1, #robot.joints do cmd[i - 1], hard[i - 1], taken[i - 1], taken_cmd[i - 1] = c.q[i], c.h[i], 0, 0 end
    cmd[w - 1], hard[w - 1] = -0.4, 0.7
    c:sync(cmd, hard, taken, taken_cmd)
    run(c, 0.5)
    assert.equals(-0.4, c.q[w])
    assert.equals(0.7, c.h[w])
    c:request('relax')
    run(c, 0.2)
    assert.equals(0, c.h[w])
    assert.equals(1, c.owner[w], 'relax owns every joint')
    c:request('stand')
    local written = false
    for _ = 1, 10 do
      run(c, 0.008)
      written = written or c.write[w]
    end
    assert.equals('stance', c:state())
    assert.equals(params.hardnessHold, c.h[w])
    assert.is_true(written, 'the stiffened hold is written once')
    assert.is_false(c.write[w])
  end)

  it('falls, goes soft everywhere and stands up again', function()
    local c = fake({ waist = true })
    run(c, 1.2)
    local pitch = 0
    run(c, 0.5, function(s)
      if s:state() == 'stance' or s:state() == 'falling' then pitch = math.min(1.5, pitch + 0.03) end
      s.angle[2], s.gyro[2] = pitch, pitch < 1.5 and 2.5 or 0
      s.acc[1], s.acc[3] = -9.81 * math.sin(pitch), 9.81 * math.cos(pitch)
    end)
    assert.equals('falling', c:state())
    run(c, 1.5, function(s) s.angle[2], s.gyro[2], s.acc[1], s.acc[3] = 1.5, 0, -9.81, 0 end)
    assert.equals('standup_front', c:state())
    -- the stand-up drives the joints its keyframes name, not the waist
    assert.equals(0, c.owner[c.ji.waist_yaw])
    run(c, 4, function(s) s.angle[2], s.gyro[2] = s.p.bodyTilt, 0 end)
    assert.equals('stance', c:state())
  end)
end)

describe('motion on other bodies', function()
  it('walks and kicks with the joints in another bus order', function()
    local c = fake({ waist = true, reorder = true })
    assert.equals('r_hip_yaw', c.robot.joints[1])
    assert.equals('r_wrist', c.robot.joints[c.n])
    local walked = exercise(c)
    assert.is_true(walked > 0.3, 'walked ' .. walked)
  end)

  it('holds an extra arm joint the arms config does not name, drives it when named', function()
    local c = fake({ wrist = true })
    local wr = c.ji.l_wrist
    c.q[wr] = 0.2
    exercise(c)
    assert.equals(0.2, c.q[wr])
    assert.equals(0, c.owner[wr])
    local arms = Config.export('walk', { robot = 'waistbot' }).arms
    arms.l.posture.l_wrist = -0.5
    c = fake({ wrist = true, arms = arms })
    run(c, 1.5)
    assert.is_near(-0.5, c.q[c.ji.l_wrist], 1e-9)
    assert.equals(1, c.owner[c.ji.l_wrist])
  end)

  it('runs without arms in the walk config: the arm joints hold', function()
    local c = fake({ arms = {} })
    local el = c.ji.l_el
    c.q[el] = 0.7
    exercise(c)
    assert.equals(0.7, c.q[el])
    assert.equals(0, c.owner[el])
    c:request('relax')
    run(c, 0.1)
    c:request('stand')
    run(c, 1.5)
    assert.equals('stance', c:state())
  end)

  it('refuses an arms config naming an unknown joint, naming the key', function()
    local ok, err = pcall(fake, { arms = { l = { posture = { l_elbow = 0 } } } })
    assert.is_false(ok)
    assert.matches("key 'arms.l.posture' names unknown joint 'l_elbow'", err, 1, true)
  end)
end)

describe('a joint taken by a caller', function()
  it("gets the caller's command while motion walks, and behavior's again once released", function()
    local c = fake({})
    local pan = c.ji.head_pan
    run(c, 1.5)
    c:request('walk')
    c.vel_cmd[1] = 0.2
    c.head[1] = -0.3
    run(c, 0.5)
    assert.equals(-0.3, c.q[pan])
    c.taken[pan], c.taken_q[pan] = true, 0.5
    run(c, 0.5)
    assert.equals(0.5, c.q[pan])
    assert.equals(2, c.owner[pan])
    assert.is_true(c.write[pan])
    assert.equals('walk', c:state())
    -- a request for walking releases the joints the walk owns (main.lua clears them with ctl:needs)
    local needs = {}
    for _, i in ipairs(c:needs('walk')) do needs[i] = true end
    assert.is_true(needs[pan])
    c.taken[pan] = false
    run(c, 0.1)
    assert.equals(-0.3, c.q[pan])
    assert.equals(1, c.owner[pan])
  end)
end)
