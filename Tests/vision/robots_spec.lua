-- luacheck: std +busted
-- Robot detection (Player/Vision/detect_robots.lua, through the pipeline) on frames ray-cast by
-- the test: green ground, a grey wall above the horizon, another robot as a grey upright cylinder
-- (0.1 m radius, 0.52 m tall: an OP3) with a jersey band of its team's colour (the sim's red or
-- blue), seen from the OP3's camera pose: its foot point against the truth, its team, and no robot
-- where there is none (the ball neither). The world model's obstacles come from these.
local ffi = require('ffi')
local pipeline = require('Vision.pipeline')

local rc = require('Tests.vision.raycast_camera')
local W, H, vcfg, ccfg, model, q0, pose_for = rc.W, rc.H, rc.vcfg, rc.ccfg, rc.model, rc.q0, rc.pose_for
local RADIUS, HEIGHT = 0.1, 0.52
local JERSEY = { [0] = { 72, 195, 98 }, [1] = { 83, 107, 212 } } -- blue, red (YUV)

-- a frame with a robot of `team` at (rx, ry) on the ground (nil: none), a ball at (bx, by) or none, and
-- more robots ({ x, y, team } each)
local function render(pose, rx, ry, team, bx, by, more)
  local robots = { rx and { rx, ry, team } or nil }
  for _, r in ipairs(more or {}) do robots[#robots + 1] = r end
  local cx, cy, cz = pose[1], pose[2], pose[3]
  local ground = cz - pose.height
  return rc.render(pose, function(dx, dy, dz)
    local Y, U, V = 150, 128, 128          -- grey wall
    local t_hit = math.huge
    if dz < 0 then Y, U, V = 99, 95, 86 t_hit = (ground - cz) / dz end -- green ground
    for _, r in ipairs(robots) do -- the cylinder's side: |(c + t d - r)_xy| = RADIUS; the nearest hit
      local ox, oy = cx - r[1], cy - r[2]
      local a, b, c = dx * dx + dy * dy, 2 * (ox * dx + oy * dy), ox * ox + oy * oy - RADIUS * RADIUS
      local disc = b * b - 4 * a * c
      if disc >= 0 then
        local t = (-b - math.sqrt(disc)) / (2 * a)
        local z = cz + t * dz - ground
        if t > 0 and t < t_hit and z >= 0 and z <= HEIGHT then
          t_hit = t
          if z > 0.25 and z < 0.38 then Y, U, V = JERSEY[r[3]][1], JERSEY[r[3]][2], JERSEY[r[3]][3]
          else Y, U, V = 120, 128, 128 end
        end
      end
    end
    if bx and rc.ball_hit(pose, dx, dy, dz, bx, by, 0.07) then Y, U, V = 147, 45, 205 end -- the ball
    return Y, U, V
  end)
end

local function detect(buf, pan, tilt)
  local vp = assert(pipeline.new(vcfg, ccfg, model))
  local q = {}
  for i = 1, #q0 do q[i] = 0 end
  local det = assert(vp:process({ yuyv = buf, width = W, height = H, head = ffi.new('double[2]', pan, tilt) },
    q, { 0, 0 }))
  return det.robots
end

describe('robot detection', function()
  it('finds a robot standing on the field, its foot point and its jersey colour', function()
    for k, case in ipairs({ { 1.2, 0.2, 1, 0.0 }, { 2.0, -0.5, 0, 0.2 }, { 0.8, -0.3, 1, -0.3 } }) do
      local rx, ry, team, pan = case[1], case[2], case[3], case[4]
      local pose = pose_for(pan, -0.3)
      local robots = detect(render(pose, rx, ry, team), pan, -0.3)
      assert.are.equal(1, robots.n, 'case ' .. k)
      local r = robots[1]
      -- the foot point is the cylinder's near side: within its radius of the centre
      local e = math.sqrt((r.x - rx) ^ 2 + (r.y - ry) ^ 2)
      assert.is_true(e < RADIUS + 0.1, string.format('case %d: foot (%.2f, %.2f), robot at (%.2f, %.2f)', k, r.x, r.y,
        rx, ry))
      assert.are.equal(team, r.team, 'case ' .. k)
    end
  end)

  it('sees a robot of the other team beside a nearer one apart, however narrow the part it shows', function()
    -- the far one shows 0.08 m at the near one's range: an arm's width, merged before the colours counted
    local pose = pose_for(0, -0.3)
    local robots = detect(render(pose, 1.0, 0.0, 1, nil, nil, { { 2.6, -0.43, 0 } }), 0, -0.3)
    assert.are.equal(2, robots.n)
    local near, far = robots[1], robots[2]
    assert.is_true(math.sqrt((near.x - 1.0) ^ 2 + near.y ^ 2) < RADIUS + 0.1,
      string.format('near one at (%.2f, %.2f)', near.x, near.y))
    assert.is_true(math.sqrt((far.x - 2.6) ^ 2 + (far.y + 0.43) ^ 2) < RADIUS + 0.15,
      string.format('far one at (%.2f, %.2f)', far.x, far.y))
    assert.are.same({ 1, 0 }, { near.team, far.team })
  end)

  it('takes nothing inside its own footprint for a robot (its own feet and arms), what stands beyond it yes', function()
    local pose = pose_for(0, -1.0)
    local inside = detect(render(pose, 0.3, 0.0, 1), 0, -1.0)   -- foot point 0.2 m ahead: vision.robots.self_x
    assert.are.equal(0, inside.n)
    local beyond = detect(render(pose, 0.45, 0.0, 1), 0, -1.0)
    assert.are.equal(1, beyond.n)
    assert.is_true(math.abs(beyond[1].x - 0.45) < RADIUS + 0.1, string.format('foot at %.2f', beyond[1].x))
  end)

  it('sees no robot on an empty field, nor the ball', function()
    local pose = pose_for(0, -0.3)
    assert.are.equal(0, detect(render(pose), 0, -0.3).n)
    assert.are.equal(0, detect(render(pose, nil, nil, nil, 1.0, 0.1), 0, -0.3).n)
  end)
end)
