-- luacheck: std +busted
-- The behavior (world model + game/head/body machines) closing the loop with an idealised robot:
-- a kinematic stand-in for the motion process and the camera (the robot moves exactly as
-- commanded, the camera sees what is inside its field of view with range noise, a kick or a kick
-- out of the walk sends the ball off). It checks the soccer logic on its own -- localization from goal posts, approach,
-- alignment, kick -- before physics gets a say; the sim scenario (Tests/scenarios/) checks the rest.
local shm = require('shm')
local Motion = require('Motion')

local HALF_FOV = 0.49      -- rad, half the horizontal field of view (640x480, 43.3 deg vertical)
local STEP = 0.024         -- s per behavior step (3 DCM ticks)

local function lcg(seed)
  local s = seed * 7919 + 17
  return function()
    s = (s * 1103515245 + 12345) % 2147483648
    return s / 2147483648
  end
end

local function wrap(a) return (a + math.pi) % (2 * math.pi) - math.pi end

-- Plays from a seeded start until a goal or `limit` seconds; returns goal (bool), time, own goal.
local function play(behavior, seed, limit)
  local sensor, vision, motion = shm.open('dcm.sensor'), shm.open('vision'), shm.open('motion')
  local rnd = lcg(seed)
  local rx, ry, ra = -4.2 + 3.9 * rnd(), -2.7 + 5.4 * rnd(), -math.pi + 2 * math.pi * rnd()
  local bx, by
  repeat bx, by = -4.0 + 3.7 * rnd(), -2.5 + 5.0 * rnd() until (bx - rx) ^ 2 + (by - ry) ^ 2 > 0.25
  local bvx, bvy = 0, 0
  local ox, oy, oa = 0, 0, 0 -- odometry
  local kick_until = -1
  local walk_kick_seq, walk_kick_at = motion.kick_seq[0], nil
  local noise = lcg(seed + 1000)
  local t0 = sensor.time[0]
  local posts = { { 4.5, 1.3 }, { 4.5, -1.3 }, { -4.5, 1.3 }, { -4.5, -1.3 } }
  local n = 0
  while sensor.time[0] - t0 < limit do
    n = n + 1
    -- motion stand-in: kicks, then walking as commanded (odometry exact)
    local req = Motion.requested()
    local t = sensor.time[0]
    if (req == 'kick_left' or req == 'kick_right') and kick_until < 0 then
      kick_until = t + 1.0
      motion.state[0] = Motion.INDEX[req]
      local c, s = math.cos(-ra), math.sin(-ra)
      local lx, ly = c * (bx - rx) - s * (by - ry), s * (bx - rx) + c * (by - ry)
      local foot = req == 'kick_left' and 0.05 or -0.05
      if lx > 0.05 and lx < 0.3 and math.abs(ly - foot) < 0.08 then
        local speed = 2.5
        bvx, bvy = speed * math.cos(ra), speed * math.sin(ra)
      end
    end
    if kick_until >= 0 and t >= kick_until then
      kick_until = -1
      motion.state[0] = Motion.INDEX.stance
      motion.request[0] = Motion.INDEX.stance
    end
    -- a kick out of the walk (Walk.kick): taken a step later, the robot walking on
    if motion.kick_seq[0] ~= walk_kick_seq then
      walk_kick_seq = motion.kick_seq[0]
      if motion.kick_request[0] ~= 0 then walk_kick_at = t + 0.3 end
    end
    if walk_kick_at and t >= walk_kick_at then
      walk_kick_at = nil
      motion.kicks[0] = motion.kicks[0] + 1
      local c, s = math.cos(-ra), math.sin(-ra)
      local lx, ly = c * (bx - rx) - s * (by - ry), s * (bx - rx) + c * (by - ry)
      local foot = motion.kick_request[1] == 0 and 0.05 or -0.05
      if lx > 0.05 and lx < 0.35 and math.abs(ly - foot) < 0.08 then
        bvx, bvy = 1.6 * math.cos(ra), 1.6 * math.sin(ra)
      end
    end
    if kick_until < 0 then
      local walking = req == 'walk'
      motion.state[0] = walking and Motion.INDEX.walk or Motion.INDEX.stance
      if walking then
        local vx, vy, va = motion.velocity[0], motion.velocity[1], motion.velocity[2]
        local c, s = math.cos(ra), math.sin(ra)
        rx, ry = rx + (c * vx - s * vy) * STEP, ry + (s * vx + c * vy) * STEP
        ra = wrap(ra + va * STEP)
        local oc, os = math.cos(oa), math.sin(oa)
        ox, oy, oa = ox + (oc * vx - os * vy) * STEP, oy + (os * vx + oc * vy) * STEP, oa + va * STEP
        -- the body shoves the ball out of its way
        local dx, dy = bx - rx, by - ry
        local d = math.sqrt(dx * dx + dy * dy)
        if d < 0.12 then bx, by = rx + dx / d * 0.12, ry + dy / d * 0.12 end
      end
    end
    motion.odometry[0], motion.odometry[1], motion.odometry[2] = ox, oy, oa
    sensor.angle[2] = ra -- a perfect IMU yaw
    -- ball rolls
    bx, by = bx + bvx * STEP, by + bvy * STEP
    bvx, bvy = bvx * math.exp(-0.8 * STEP), bvy * math.exp(-0.8 * STEP)
    if by > 3.2 or by < -3.2 then bvy = -bvy end
    if bx < -4.7 then bvx = -bvx end
    if bx > 4.5 and math.abs(by) < 1.3 then return true, sensor.time[0] - t0, false end
    if bx > 4.7 then bvx = -bvx * 0.5 bx = 4.7 end
    -- camera stand-in, 30 Hz: what lies within the field of view around the head's pan
    if n % 2 == 0 then
      local pan = motion.head_command[0]
      local c, s = math.cos(-ra), math.sin(-ra)
      local function sees(px, py, range)
        local lx, ly = c * (px - rx) - s * (py - ry), s * (px - rx) + c * (py - ry)
        local d = math.sqrt(lx * lx + ly * ly)
        if d > range or math.abs(wrap(math.atan2(ly, lx) - pan)) > HALF_FOV then return nil end
        local k = 1 + 0.05 * (2 * noise() - 1)
        return lx * k, ly * k
      end
      vision:write(function(v)
        v.frame[0] = v.frame[0] + 1
        v.time[0] = sensor.time[0]
        local lx, ly = sees(bx, by, 5.0)
        v.ball_detected[0] = lx and 1 or 0
        if lx then v.ball_position[0], v.ball_position[1] = lx, ly end
        local k = 0
        for _, p in ipairs(posts) do
          local px, py = sees(p[1], p[2], 7.0)
          if px and k < 2 then
            v.goal_position[2 * k], v.goal_position[2 * k + 1] = px, py
            k = k + 1
          end
        end
        v.goal_posts[0] = k
      end)
    end
    sensor.tick[0] = sensor.tick[0] + 3
    sensor.time[0] = sensor.time[0] + STEP
    behavior:step()
    if os.getenv('TRACE') and n % 42 == 0 then
      local w = behavior.world
      print(string.format('# t=%5.1f robot=(%.2f,%.2f,%.2f) est=(%.2f,%.2f,%.2f c%.2f) ball=(%.2f,%.2f)'
        .. ' est=(%.2f,%.2f age %.1f) %s/%s',
        sensor.time[0] - t0, rx, ry, ra, w.pose.x, w.pose.y, w.pose.a, w.pose.confidence, bx, by,
        select(1, w:ball_field()), select(2, w:ball_field()), w:ball_age(), behavior.body:state(),
        behavior.head:state()))
    end
  end
  return false, limit, false
end

describe('behavior with an idealised robot', function()
  teardown(function()
    if os.getenv('ROBOT_ID') then for _, name in ipairs(shm.block_names()) do shm.unlink(name) end end
  end)

  it('scores from seeded starts anywhere in the own half', function()
    local goals, times = 0, {}
    local seeds = 10
    for seed = tonumber(os.getenv('SEED') or 1), tonumber(os.getenv('SEED') or seeds) do
      -- a fresh behavior per run: it knows nothing of the previous one
      package.loaded['Behavior.behavior'] = nil
      local behavior = require('Behavior.behavior').new({ port = 0, team_port = 0, fresh = true })
      behavior.gc.state = 3 -- playing (no GameController in this test)
      behavior.gc.gc_seen = true
      -- the stand-in models a kick, not the feet pushing a ball along: play by kicking
      behavior.cfg.body.dribble.enabled = false
      local ok, t = play(behavior, seed, 120)
      behavior:close()
      print(string.format('# seed %d: %s after %.1f s', seed, ok and 'goal' or 'no goal', t))
      if ok then goals = goals + 1 times[#times + 1] = t end
    end
    table.sort(times)
    print(string.format('# idealised robot: %d/%d goals, median %.1f s', goals, seeds,
      times[math.max(1, math.floor((#times + 1) / 2))] or -1))
    assert.is_true(goals >= 9, goals .. '/10 goals')
  end)
end)
