-- luacheck: std +busted
-- The camera model of Player/Vision/project.lua with the body's calibration (camera.lua): without
-- distortion it is the plain pinhole, number for number; with it, a point's pixel projects back to
-- the point, and the pixel is where OpenCV's radial model puts it.
local project = require('Vision.project')
local Config = require('Config')
local kinematics = require('kinematics')

local ccfg = Config.load('camera', nil, { robot = 'op3', platform = 'Sim' })
local model = assert(kinematics.load({ robot = 'op3' }))

local function pose_for(pan, tilt)
  local q = {}
  for i = 1, #model.joints do q[i] = 0 end
  q[1], q[2] = pan, tilt
  return (model:camera_pose(q, { 0, 0 }))
end

describe('the calibrated camera', function()
  it('is the pinhole of fovy exactly when the distortion is zero', function()
    local plain = project.camera(ccfg.width, ccfg.height, ccfg.fovy)
    local calib = { intrinsics = ccfg.intrinsics, distortion = { k1 = 0, k2 = 0 } }
    local cm = project.camera(ccfg.width, ccfg.height, ccfg.fovy, calib)
    assert.are.equal(plain.f, cm.fx)
    assert.are.equal(plain.cx, cm.cx)
    assert.are.equal(plain.cy, cm.cy)
    local pose = pose_for(0.3, -0.4)
    for _, p in ipairs({ { 1.0, 0.2 }, { 2.5, -0.8 }, { 0.5, 0.1 } }) do
      local u1, v1 = project.to_image(plain, pose, p[1], p[2], 0)
      local u2, v2 = project.to_image(cm, pose, p[1], p[2], 0)
      assert.are.equal(u1, u2)
      assert.are.equal(v1, v2)
      local x1, y1 = project.to_ground(plain, pose, 100.25, 300.5, 0)
      local x2, y2 = project.to_ground(cm, pose, 100.25, 300.5, 0)
      assert.are.equal(x1, x2)
      assert.are.equal(y1, y2)
    end
  end)

  it('undistorts a pixel before projecting it to the ground (round trip over the image)', function()
    local cm = project.from_config(ccfg)
    assert.is_true(cm.k1 ~= 0 or cm.k2 ~= 0, 'the OP3 body has a lens distortion')
    local worst, n = 0, 0
    for _, head in ipairs({ { 0, -0.3 }, { 0.6, -0.6 }, { -0.8, -0.2 } }) do
      local pose = pose_for(head[1], head[2])
      for u = 10, 630, 40 do
        for v = 10, 470, 40 do
          local x, y = project.to_ground(cm, pose, u, v, 0)
          if x then
            local u2, v2 = project.to_image(cm, pose, x, y, 0)
            worst = math.max(worst, math.abs(u2 - u) + math.abs(v2 - v))
            n = n + 1
          end
        end
      end
    end
    assert.is_true(n > 100)
    assert.is_true(worst < 1e-6, 'round trip error ' .. worst .. ' px')
  end)

  it('puts a point where the radial model says', function()
    local cm = project.from_config(ccfg)
    local pose = pose_for(0.4, -0.5)
    local u, v = project.to_image(cm, pose, 1.2, 0.5, 0)
    -- the pinhole pixel, then x_d = x (1 + k1 r^2 + k2 r^4) about the principal point
    local plain = project.camera(ccfg.width, ccfg.height, ccfg.fovy, { intrinsics = ccfg.intrinsics })
    local pu, pv = project.to_image(plain, pose, 1.2, 0.5, 0)
    local x, y = (pu - cm.cx) / cm.fx, (pv - cm.cy) / cm.fy
    local r2 = x * x + y * y
    local k = 1 + cm.k1 * r2 + cm.k2 * r2 * r2
    assert.is_true(math.abs(u - (cm.cx + cm.fx * x * k)) < 1e-9)
    assert.is_true(math.abs(v - (cm.cy + cm.fy * y * k)) < 1e-9)
    assert.is_true(math.abs(u - pu) + math.abs(v - pv) > 0.1, 'the lens moves this pixel')
  end)
end)
