-- luacheck: std +busted
-- The world model: ball filter moved by odometry; pose particle filter from goal posts.
local ball_filter = require('World.ball_filter')
local pose_filter = require('World.pose_filter')
local World = require('World.world')

local bcfg = { process_noise = 0.5, meas_noise = 0.08, deceleration = 0.6, friction = 0.1, max_speed = 5,
  reset_after = 2, jump_distance = 0.6 }
local field = { length = 9, width = 6, goal_width = 2.6 }
local pcfg = { particles = 300, prior = { -4.5, 0, -3, 3 }, odom_trans_noise = 0.15, odom_rot_noise = 0.1,
  odom_rot_per_m = 0.05, post_range_noise = 0.15, post_bearing_noise = 0.12, outlier = 0.05,
  inject_fraction = 0.01, margin = 0.5, roughen_position = 0.03, roughen_angle = 0.02,
  reset_below = 0.5, reset_fraction = 0.05, gate_confidence = 0.6, gate_fit = 0.01,
  project_fraction = 0.05, project_lost = 0.3, project_max_jump = 1.0, side_confidence = 0.5,
  side_tolerance = 1.57, own_half_margin = 0.3, placement = 'anywhere' }

describe('ball filter', function()
  it('keeps a still ball in place while the robot walks and turns', function()
    local f = ball_filter.new(bcfg)
    f:observe(2.0, 0.0, 0)
    -- the robot walks 1 m forward then turns 90 degrees left: the ball is 1 m ahead, then to the right
    for _ = 1, 100 do f:move_robot(0.01, 0, 0) f:predict(0.01) end
    assert.is_near(1.0, f.x, 1e-6)
    f:move_robot(0, 0, math.pi / 2)
    assert.is_near(0.0, f.x, 1e-6)
    assert.is_near(-1.0, f.y, 1e-6)
  end)

  it('estimates a rolling ball\'s velocity from sightings', function()
    local f = ball_filter.new(bcfg)
    local t = 0
    -- released at 1 m/s, slowing down at 0.6 m/s^2 (rolling resistance)
    for k = 0, 30 do
      t = k * 0.033
      local x = 1.0 + t - 0.3 * t * t
      if k > 0 then f:predict(0.033) end
      f:observe(x, 0.5, t)
    end
    assert.is_near(1.0 - 0.6 * t, f.vx, 0.25)
    assert.is_near(0, f.vy, 0.1)
  end)

  it('lets a slow ball stop within centimetres when it is not seen', function()
    local f = ball_filter.new(bcfg)
    f:observe(0.3, 0, 0)
    f.vx = 0.3 -- pushed by a dribbling foot
    for _ = 1, 100 do f:predict(0.02) end
    -- 0.3^2 / (2 * 0.6) = 0.075 m, a little less with drag
    assert.is_true(f.x > 0.3 + 0.06 and f.x < 0.3 + 0.08, 'x ' .. f.x)
    assert.are.equal(0, f.vx)
  end)
end)

describe('pose filter', function()
  local posts = { { 4.5, 1.3 }, { 4.5, -1.3 }, { -4.5, 1.3 }, { -4.5, -1.3 } }
  local function seen(x, y, a, idx)
    local list = {}
    for _, k in ipairs(idx) do
      local dx, dy = posts[k][1] - x, posts[k][2] - y
      local c, s = math.cos(-a), math.sin(-a)
      list[#list + 1] = { c * dx - s * dy, s * dx + c * dy }
    end
    return list
  end

  it('localizes from the own half by turning and seeing both goals', function()
    local f = pose_filter.new(field, pcfg, World.make_rng(3))
    local x, y, a = -2.0, 1.0, 2.0
    -- turn on the spot in steps, seeing whichever goal is ahead (within +-0.8 rad)
    for _ = 1, 3 do
      for _ = 1, 63 do
        a = pose_filter.wrap(a + 0.1)
        f:move(0, 0, 0.1)
        local vis = {}
        for k, p in ipairs(posts) do
          local b = pose_filter.wrap(math.atan2(p[2] - y, p[1] - x) - a)
          if math.abs(b) < 0.8 then vis[#vis + 1] = k end
        end
        if #vis > 0 then f:observe_posts(seen(x, y, a, vis)) end
      end
    end
    local ex, ey, ea, conf = f:estimate()
    assert.is_near(x, ex, 0.4)
    assert.is_near(y, ey, 0.4)
    assert.is_near(0, pose_filter.wrap(ea - a), 0.15)
    assert.is_true(conf > 0.3)
  end)

  -- A goalkeeper in its goal facing the field sees only the far goal's posts: its pose and the
  -- mirror pose in the other goal (4.2, 0, pi) see exactly the same. A belief spread over the whole
  -- field (lost, e.g. after a fall) must come back to its own goal, never to the other one.
  local function lost_keeper(seed, side_known)
    local f = pose_filter.new(field, pcfg, World.make_rng(seed))
    f:set_pose(-4.2, 0, 0, 0.02) -- placed: the side is known
    if not side_known then f.side_a = nil end
    local rng = World.make_rng(seed + 100)
    for i = 1, f.n do
      f.px[i], f.py[i], f.pa[i] = -4.5 + 9 * rng(), -3 + 6 * rng(), pose_filter.wrap(2 * math.pi * rng())
    end
    f.fit = 0.1 -- the sightings contradicted the belief: re-seeding from two posts is on
    local mirrored = 0
    for k = 1, 150 do
      f:move(0, 0, 0)
      f:observe_posts(seen(-4.2, 0, 0, { 1, 2 }))
      local ex = f:estimate()
      if k > 50 and ex > 0 then mirrored = mirrored + 1 end
    end
    return f, mirrored
  end

  it('keeps a goalkeeper that lost its belief in its own goal, not the mirror one (the side)', function()
    local wrong_without = 0
    for seed = 1, 8 do
      local f, mirrored = lost_keeper(seed, true)
      local ex, ey, ea = f:estimate()
      assert.are.equal(0, mirrored, 'seed ' .. seed .. ': steps with the belief in the other half')
      assert.is_near(-4.2, ex, 0.4)
      assert.is_near(0, ey, 0.4)
      assert.is_near(0, pose_filter.wrap(ea), 0.2)
      for i = 1, f.n do assert.is_false(f:mirrored(f.pa[i])) end
      -- the same without the side: the sightings alone cannot tell the goals apart
      local _, m2 = lost_keeper(seed, false)
      if m2 > 0 then wrong_without = wrong_without + 1 end
    end
    assert.is_true(wrong_without > 0, 'without the side, some seeds end in the mirror goal')
  end)

  it('takes the side from a confident belief whose mirror is out of reach, and follows turns', function()
    local f = pose_filter.new(field, pcfg, World.make_rng(7))
    assert.is_nil(f.side_a)
    local x, y, a = -3.0, -1.0, 0.3
    for _ = 1, 60 do
      f:move(0, 0, 0)
      f:observe_posts(seen(x, y, a, { 1, 2 }))
      f:estimate()
    end
    assert.is_not_nil(f.side_a, 'the side is known')
    assert.is_near(0, pose_filter.wrap(f.side_a - a), 0.2)
    f:move(0, 0, 0.5)
    assert.is_near(0, pose_filter.wrap(f.side_a - a - 0.5), 0.2)
    -- no two-post re-seeding candidate is the mirror any more
    f.walked = math.huge
    for _, c in ipairs(f:poses_from_two_posts(seen(x, y, a + 0.5, { 1, 2 })[1], seen(x, y, a + 0.5, { 1, 2 })[2])) do
      assert.is_true(c[1] < 0, 'candidate at x ' .. c[1])
    end
    f:init_prior() -- placed anew: the side comes from the prior again
    assert.is_nil(f.side_a)
  end)

  it('follows odometry once localized', function()
    local f = pose_filter.new(field, pcfg, World.make_rng(5))
    f:set_pose(-1, 0, 0, 0.02)
    for _ = 1, 100 do f:move(0.01, 0, 0.005) end
    local ex, ey, ea = f:estimate()
    assert.is_true(ex > -0.2 and ex < 0.1)
    assert.is_true(ey > 0.05 and ey < 0.4)
    assert.is_near(0.5, ea, 0.1)
  end)
end)

describe('world', function()
  it('turns odometry readings into steps in the robot frame', function()
    local dx, dy, da = World.odom_delta({ 1, 1, math.pi / 2 }, { 1, 2, math.pi / 2 + 0.1 })
    assert.is_near(1, dx, 1e-9)
    assert.is_near(0, dy, 1e-9)
    assert.is_near(0.1, da, 1e-9)
  end)

  local wcfg = { field = field, ball = bcfg, pose = pcfg, seed = 1, ball_lost_after = 3,
    max_odometry_step = 0.5, post_min_range = 0.5, post_max_range = 4.0, post_pair_tolerance = 0.8,
    localised_confidence = 0.5 }

  it('knows the touch line it is placed on (and the side at once) from the placement and the half', function()
    local pc = setmetatable({ placement = 'right' }, { __index = pcfg })
    local w = World.new(setmetatable({ pose = pc }, { __index = wcfg }))
    assert.are.same({ -1 }, w:placement_lines(false, true))
    assert.are.same({ 1 }, w:placement_lines(false, false))   -- second half: the sides changed
    assert.are.same({ -1, 1 }, w:placement_lines(true, true))  -- put back after a penalty: either
    w.pose:imu(0.3)
    w:reset_pose(false, true)
    -- every particle on the right touch line facing in, the side known and held against the IMU
    for i = 1, w.pose.n do
      assert.is_true(math.abs(w.pose.py[i] + 3) < 0.6 and w.pose.px[i] <= 0)
    end
    assert.is_near(math.pi / 2, w.pose.side_a, 1e-9)
    w.pose:imu(0.3 + 2.0) -- the body turned 2 rad (a fall, say): the side turns with it
    assert.is_near(0, pose_filter.wrap(w.pose.side_a - math.pi / 2 - 2.0), 1e-9)
    pc.placement = 'anywhere'
    assert.is_nil(w:placement_lines(false, true))
  end)

  it('passes only plausible goal-post sightings to the pose filter', function()
    local w = World.new(wcfg)
    assert.is_nil(w:plausible_posts({}))
    assert.is_nil(w:plausible_posts({ { 0.2, 0.1 } }))                 -- too near to be a post
    assert.is_nil(w:plausible_posts({ { 5.0, 0.1 } }))                 -- too far to trust
    assert.is_nil(w:plausible_posts({ { 3.0, 0.3 }, { 3.0, -0.3 } }))  -- 0.6 m apart: not a goal
    assert.are.equal(2, #w:plausible_posts({ { 3.0, 1.3 }, { 3.0, -1.2 } }))
    local one = w:plausible_posts({ { 0.25, 0.0 }, { 3.0, 1.3 } })    -- the near one dropped
    assert.are.equal(1, #one)
    assert.are.equal(3.0, one[1][1])
  end)

  it('takes the turn from the IMU yaw changes when given', function()
    local w = World.new(wcfg)
    w.pose:set_pose(-1, 0, 0, 0.02) -- a belief with one heading, so that its turn can be read
    w:update(0, { 0, 0, 0 }, nil, 1.0)
    w:update(0.1, { 0.1, 0, 0 }, nil, 1.3) -- the walk planned no turn; the body turned 0.3 rad
    local before = w.pose.a
    w:update(0.2, { 0.1, 0, 0 }, nil, 1.6)
    local turned = ((w.pose.a - before) + math.pi) % (2 * math.pi) - math.pi
    assert.is_true(math.abs(turned - 0.3) < 0.1, 'turned ' .. turned)
  end)

  it('takes only the bearing of a robot whose feet are below the image when it is nearer', function()
    local cfg = setmetatable({ obstacles = { memory = 4, memory_out_of_view = 10, merge = 0.5, blend = 0.5,
      field_margin = 0.5, min_range = 0.3, max = 8 } }, { __index = wcfg })
    local w = World.new(cfg)
    w:observe_robots({ { x = 0.6, y = 0.0, team = -1, foot_visible = true } }, 0)
    -- then its feet are out of the image: the sighting's range (0.67 m) is an upper bound
    local r = math.sqrt(0.5 ^ 2 + 0.45 ^ 2)
    w:observe_robots({ { x = 0.5, y = 0.45, team = -1, foot_visible = false } }, 0.1)
    local o = w.obstacles[1]
    assert.are.equal(1, #w.obstacles)
    assert.is_near((0.6 + 0.5 * 0.6 / r) / 2, o.x, 1e-9) -- blended with the sighting at range 0.6
    assert.is_near(0.45 * 0.6 / r / 2, o.y, 1e-9)
    -- a sighting with the feet in the image moves it out
    local before = math.sqrt(o.x ^ 2 + o.y ^ 2)
    w:observe_robots({ { x = 0.5, y = 0.45, team = -1, foot_visible = true } }, 0.2)
    assert.is_true(math.sqrt(o.x ^ 2 + o.y ^ 2) > before + 0.03)
  end)
  it('forgets an obstacle unseen in the camera\'s view, keeps one beside it until memory_out_of_view', function()
    local cfg = setmetatable({ obstacles = { memory = 4, memory_out_of_view = 10, merge = 0.5, blend = 0.5,
      field_margin = 0.5, min_range = 0.3, max = 8 } }, { __index = wcfg })
    local w = World.new(cfg)
    local view = { pan = 0, half_fov = math.rad(28) }
    w:update(0, { 0, 0, 0 }, nil, nil, view)
    -- one ahead (in view), one beside (bearing 90 degrees: out of view)
    w:observe_robots({ { x = 1.0, y = 0.0, team = -1 }, { x = 0.0, y = 0.8, team = -1 } }, 0)
    assert.are.equal(2, #w.obstacles)
    local t = 0
    local function run_to(t_end)
      while t < t_end - 1e-9 do
        t = t + 0.1
        w:update(t, { 0, 0, 0 }, nil, nil, view)
      end
    end
    run_to(4.5)
    assert.are.equal(1, #w.obstacles)   -- the one ahead: 4 s in view without a sighting
    assert.is_near(0.8, w.obstacles[1].y, 1e-9)
    -- the head turns to it: now in view, forgotten after 4 s more of not seeing it
    view.pan = math.rad(90)
    run_to(8.0)
    assert.are.equal(1, #w.obstacles)
    run_to(8.7)
    assert.are.equal(0, #w.obstacles)
    -- never looked at: forgotten after memory_out_of_view
    view.pan = 0
    w:observe_robots({ { x = 0.0, y = -0.8, team = -1 } }, t)
    local seen = t
    run_to(seen + 9.5)
    assert.are.equal(1, #w.obstacles)
    run_to(seen + 10.5)
    assert.are.equal(0, #w.obstacles)
    -- without a view (no head angle), the plain memory
    w:observe_robots({ { x = 0.0, y = -0.8, team = -1 } }, t)
    seen = t
    while t < seen + 4.5 do t = t + 0.1 w:update(t, { 0, 0, 0 }, nil, nil, nil) end
    assert.are.equal(0, #w.obstacles)
  end)
end)
