-- luacheck: std +busted
-- Projection and ball detection on frames ray-cast by the test itself (green ground, orange
-- sphere of 0.14 m, grey above the horizon) from the OP3's camera pose (Lib/kinematics), seeded
-- random ball positions and head angles: the detector's range and bearing against the truth.
local ffi = require('ffi')
local project = require('Vision.project')
local pipeline = require('Vision.pipeline')

local rc = require('Tests.vision.raycast_camera')
local W, H, vcfg, ccfg, model, cm, q0, pose_for = rc.W, rc.H, rc.vcfg, rc.ccfg, rc.model, rc.cm, rc.q0, rc.pose_for
local R_BALL = 0.07

-- ray-cast a YUYV frame: ball at (bx, by) on the ground (nil: no ball)
local function render(pose, bx, by)
  return rc.render(pose, function(dx, dy, dz)
    if bx and rc.ball_hit(pose, dx, dy, dz, bx, by, R_BALL) then return 147, 45, 205 end -- orange ball
    if dz < 0 then return 99, 95, 86 end                                                  -- green ground
    return 150, 128, 128                                                                  -- grey wall
  end)
end

local function frame_of(buf, pan, tilt)
  local head = ffi.new('double[2]', pan, tilt)
  return { yuyv = buf, width = W, height = H, head = head }
end

describe('vision projection', function()
  it('to_image and to_ground are inverse', function()
    local pose = pose_for(0.3, -0.5)
    for _, p in ipairs({ { 1.0, 0.2 }, { 2.5, 0.8 }, { 0.6, 0.1 } }) do
      local u, v = project.to_image(cm, pose, p[1], p[2], 0)
      assert.truthy(u)
      local x, y = project.to_ground(cm, pose, u, v, 0)
      assert.is_true(math.abs(x - p[1]) < 1e-9 and math.abs(y - p[2]) < 1e-9)
    end
  end)

  it('a point straight ahead on the optical axis projects to the image centre', function()
    local pose = pose_for(0, -0.6)
    local R = pose.R
    -- optical axis hits the ground at t = height / -R[7]
    local t = pose.height / -R[7]
    local u, v = project.to_image(cm, pose, pose[1] + t * R[1], pose[2] + t * R[4], 0)
    assert.is_true(math.abs(u - W / 2) < 1e-6 and math.abs(v - H / 2) < 1e-6)
  end)
end)

describe('ball detection on ray-cast frames', function()
  local vp = assert(pipeline.new(vcfg, ccfg, model))

  it('finds the ball within 10% range and 3 degrees bearing', function()
    math.randomseed(5)
    local tried, found, worst_range, worst_bearing = 0, 0, 0, 0
    while tried < 12 do
      local pan = (math.random() - 0.5) * 1.6
      local tilt = 0.1 - math.random() * 1.0
      local pose = pose_for(pan, tilt)
      local range = 0.3 + math.random() * 2.7
      local bearing = pan + (math.random() - 0.5) * 0.5
      local bx, by = range * math.cos(bearing), range * math.sin(bearing)
      local u, v = project.to_image(cm, pose, bx, by, R_BALL)
      -- fully in view (a margin of the ball's apparent radius)
      local rpx = u and cm.f * R_BALL / math.sqrt((bx - pose[1]) ^ 2 + (by - pose[2]) ^ 2 + pose.height ^ 2)
      if u and u > rpx + 2 and u < W - rpx - 2 and v > rpx + 2 and v < H - rpx - 2 then
        tried = tried + 1
        local det = vp:process(frame_of(render(pose, bx, by), pan, tilt), q0, { 0, 0 })
        local ball = det.ball
        if ball.detected then
          found = found + 1
          local r_est, r_true = math.sqrt(ball.x ^ 2 + ball.y ^ 2), math.sqrt(bx ^ 2 + by ^ 2)
          worst_range = math.max(worst_range, math.abs(r_est - r_true) / r_true)
          worst_bearing = math.max(worst_bearing, math.abs(math.atan2(ball.y, ball.x) - math.atan2(by, bx)))
        end
      end
    end
    assert.are.equal(tried, found)
    assert.is_true(worst_range <= 0.10, 'range error ' .. worst_range)
    assert.is_true(worst_bearing <= math.rad(3), 'bearing error ' .. math.deg(worst_bearing))
  end)

  it('reports no ball on a frame without one', function()
    for _, t in ipairs({ 0.0, -0.4, -0.8 }) do
      local det = vp:process(frame_of(render(pose_for(0.2, t)), 0.2, t), q0, { 0, 0 })
      assert.is_false(det.ball.detected)
    end
  end)

  it('refuses a frame of the wrong size without raising', function()
    local det, err = vp:process({ yuyv = ffi.new('uint8_t[8]'), width = 2, height = 2,
                                  head = ffi.new('double[2]') }, q0, { 0, 0 })
    assert.is_nil(det)
    assert.truthy(err:find('2x2'))
  end)
end)
