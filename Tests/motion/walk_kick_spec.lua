-- luacheck: std +busted
-- A kick out of the walk (Player/Motion/walk_kick.lua) on both engines, without a robot: the kick
-- takes the next step that swings the kicking foot, replaces its swing (wind-up behind, strike
-- through the ball, landing where the walk would have put the foot) and the walk steps on.
local Walk = require('Motion.walk')
local WalkPreview = require('Motion.walk_preview')
local WalkKick = require('Motion.walk_kick')
local fixture = require('Tests.motion.walk_fixture')

local robot, model, dt = fixture.robot, fixture.model, fixture.dt

local function new_walk(engine)
  local p = fixture.copy(fixture.params)
  local w = engine.new(p, model, dt):bind(robot)
  local k = w:extend(WalkKick.new(p))
  return w, k, p
end

-- walks at vx for `before` s, asks for a kick, walks `after` s more; records each tick
local function run(engine, kind, foot, ball, before, after, vx)
  local w, k, p = new_walk(engine)
  local q = {}
  for i = 1, #robot.joints do q[i] = 0 end
  w:set_velocity(vx or 0.12, 0, 0)
  w:start()
  local rec = { steps = {}, ticks = {} }
  local n1, n2 = math.floor(before / dt + 0.5), math.floor((before + after) / dt + 0.5)
  local last_steps = w.stats.steps
  for i = 1, n2 do
    if i == n1 then
      local b = ball and Walk.pose_global(ball, w.uTorso) or nil
      assert(k:request(kind, foot, b, i * dt))
      rec.asked_steps = w.stats.steps
    end
    w:advance(dt)
    assert.equal(0, w:joint_angles(q, nil, dt))
    if w.stats.steps ~= last_steps then
      last_steps = w.stats.steps
      rec.steps[#rec.steps + 1] = { n = w.stats.steps, T = w.T, support = w.support, kick = k.cur ~= nil,
        l2 = { unpack(w.uLeft2) }, r2 = { unpack(w.uRight2) }, sup = k.cur and k.cur.sup }
    end
    if k.cur then
      rec.ball_rel = rec.ball_rel or k.cur.ball
      local f = foot == 'left' and w.uLeft or w.uRight
      local rel = Walk.pose_relative(f, k.cur.sup)
      rec.ticks[#rec.ticks + 1] = { x = rel[1], y = (foot == 'left' and 1 or -1) * rel[2], z = w.swing_z,
        hip = k.joint.hip, sup = foot == 'left' and { unpack(w.uRight) } or { unpack(w.uLeft) } }
    end
  end
  return rec, k, p, w
end

for name, engine in pairs({ analytic = Walk, preview = WalkPreview }) do
  describe('walk kick (' .. name .. ' engine)', function()
    it('kicks on the next step that swings the kicking foot, with its own duration, and walks on', function()
      for _, foot in ipairs({ 'left', 'right' }) do
        local rec, k, p = run(engine, 'forward', foot, nil, 2.0, 2.0)
        local kicks = 0
        for i, s in ipairs(rec.steps) do
          if s.kick then
            kicks = kicks + 1
            -- the swing foot is the kicking foot, the first such step after the request
            assert.equal(foot == 'left' and Walk.RIGHT or Walk.LEFT, s.support)
            assert.is_true(s.n - rec.asked_steps <= 2)
            assert.is_near(p.walkKick.forward.tStep, s.T, dt / 2 + 1e-9)
            assert.is_true(rec.steps[i + 1] ~= nil) -- steps went on
          end
        end
        assert.equal(1, kicks)
        assert.equal(1, k.count)
        assert.equal(0, k:phase())
      end
    end)

    it('winds up behind, strikes through the ball, lands where the walk would; the support foot stays', function()
      local ball = { 0.22, 0.06, 0 } -- robot frame, ahead of the left foot
      local rec, _, p = run(engine, 'forward', 'left', ball, 2.0, 1.5)
      local cfg = p.walkKick.forward
      local minx, maxx, maxz, hip = math.huge, -math.huge, 0, 0
      for _, t in ipairs(rec.ticks) do
        minx, maxx, maxz = math.min(minx, t.x), math.max(maxx, t.x), math.max(maxz, t.z)
        hip = math.min(hip, t.hip)
        assert.is_true(t.x >= cfg.reach.x[1] - 1e-9 and t.x <= cfg.reach.x[2] + 1e-9)
        assert.is_true(t.y >= cfg.reach.y[1] - 1e-3)
        assert.same(rec.ticks[1].sup, t.sup)
      end
      -- the wind-up goes back to the reach box's rear end, behind the support ankle
      assert.is_true(minx < 0, 'wind-up behind the support ankle: ' .. minx)
      assert.is_near(cfg.reach.x[1], minx, 1e-3)
      -- the contact point (the ball's x, less the foot's face and the ball's depth) is passed
      local kick_step
      for _, s in ipairs(rec.steps) do if s.kick then kick_step = s end end
      -- the ball (as the kick step saw it, from the support ankle) is met: the contact point passed
      assert.is_true(rec.ball_rel[1] > 0.1 and rec.ball_rel[1] < ball[1])
      assert.is_true(maxx > rec.ball_rel[1] - cfg.contact.x, 'strike reaches the ball: ' .. maxx)
      assert.is_true(maxz >= 0.04)
      assert.is_true(hip < -0.1, 'hip swings forward at the strike')
      -- landing: the last tick's foot is the step's landing target (z 0)
      local last = rec.ticks[#rec.ticks]
      local land = Walk.pose_relative(kick_step.l2, kick_step.sup)
      assert.is_near(land[1], last.x, 2e-3)
      assert.is_near(0, last.z, 1e-3)
    end)

    it('waits for a step no faster than walkKick.maxSpeed', function()
      local rec, k, p = run(engine, 'forward', 'left', nil, 2.0, 0.5, 0.3)
      assert.is_true(0.3 > p.walkKick.maxSpeed[1])
      for _, s in ipairs(rec.steps) do assert.is_false(s.kick) end
      assert.equal(0, k.count)
      assert.equal(1, k:phase()) -- still asked (the motion process drops it after walkKick.expire)
    end)

    it('drops a request no step honours in time and refuses bad kinds', function()
      local _, k, p = new_walk(engine)
      local expire = p.walkKick.expire
      assert.is_nil(k:request('volley', 'left'))
      assert.is_nil(k:request('forward', 'middle'))
      assert.is_true(k:request('side', 'right', nil, 1.0))
      assert.equal(1, k:phase())
      k:expire(1.0 + expire - 0.1, true)
      assert.equal(1, k:phase())
      k:expire(1.0 + expire + 0.1, true)
      assert.equal(0, k:phase())
    end)

    it('kicks a ball beyond ballMax from a later step of the foot, once the walk has brought it nearer', function()
      local _, _, p0 = new_walk(engine)
      local far = p0.walkKick.forward.ballMax
      assert.is_true(far ~= nil, 'the config sets walkKick.forward.ballMax')
      local function kick_step(rec)
        for _, s in ipairs(rec.steps) do if s.kick then return s.n end end
      end
      -- the ball 0.1 m beyond it (robot frame, ahead of the left foot): at 0.12 m/s the walk needs
      -- more than a step pair to bring it within; without ballMax it is kicked within 2 steps
      local rec, k = run(engine, 'forward', 'left', { far + 0.1, 0.06, 0 }, 2.0, 2.5)
      assert.equal(1, k.count)
      assert.is_true(kick_step(rec) - rec.asked_steps > 2, 'waited past the first step of the foot')
      assert.is_true(rec.ball_rel[1] <= far, 'kicked from within ballMax: ' .. rec.ball_rel[1])
      -- and a ball within it is kicked on the first step of the foot, as before
      local near, kn = run(engine, 'forward', 'left', { far - 0.03, 0.06, 0 }, 2.0, 1.5)
      assert.equal(1, kn.count)
      assert.is_true(kick_step(near) - near.asked_steps <= 2)
    end)
  end)
end
