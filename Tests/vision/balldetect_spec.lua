-- luacheck: std +busted
-- The white-ball path's configuration and model file: the ball kind chosen by vision.ball.kind, clear
-- errors for a bad kind or model file, and the detector finding a ball the test paints into a frame
-- (a white disc with dark patches on green, lit as the sim lights its ball, from the OP3's camera
-- pose) where the truth puts it.
local ffi = require('ffi')
local Config = require('Config')
local kinematics = require('kinematics')
local pipeline = require('Vision.pipeline')
local project = require('Vision.project')
local balldetect = require('balldetect')

local W, H = 640, 480
-- a still camera: no exposure to date the frame back by (camera.lua exposure_time)
local ccfg = { width = W, height = H, fovy = math.rad(43.3), head_joint = { 0, 1 }, exposure_time = 0 }
-- (Config.load may hand out the same tables again: both keys are set every time)
local function vision(kind, model)
  local v = Config.load('vision', nil, { robot = 'op3', platform = 'Sim' })
  v.ball.kind = kind
  v.ball.white.model = model or 'Config/common/ball_white.mlp'
  return v
end

local function tmpfile(text)
  local path = os.tmpname()
  local f = assert(io.open(path, 'w'))
  f:write(text)
  f:close()
  return path
end

describe('ball kind', function()
  it('an unknown kind is refused, naming the key', function()
    local vp, err = pipeline.new(vision('purple'), ccfg, nil)
    assert.is_nil(vp)
    assert.truthy(err:find('vision.ball.kind', 1, true))
  end)
  it('orange has no classifier, white loads the committed one', function()
    assert.is_nil(assert(pipeline.new(vision('orange'), ccfg, nil)).mlp)
    assert.is_not_nil(assert(pipeline.new(vision('white'), ccfg, nil)).mlp)
  end)
end)

describe('model file', function()
  it('a missing file is named', function()
    local vp, err = pipeline.new(vision('white', '/nonexistent/ball.mlp'), ccfg, nil)
    assert.is_nil(vp)
    assert.truthy(err:find('/nonexistent/ball.mlp', 1, true))
  end)
  it('a wrong header or a short file names the file and what is wrong', function()
    local bad = tmpfile('hrp-ball-mlp 1 10 4 1.4\n')
    local m, err = balldetect.load_model(bad)
    assert.is_nil(m)
    assert.truthy(err:find(bad, 1, true) and err:find('NIN 10', 1, true))
    local short = tmpfile(string.format('hrp-ball-mlp 1 %d 2 1.4\n1 2 3\n', balldetect.NFEAT))
    m, err = balldetect.load_model(short)
    assert.is_nil(m)
    assert.truthy(err:find(short, 1, true) and err:find('W1 element 4', 1, true))
    os.remove(bad)
    os.remove(short)
  end)
end)

describe('white ball on a painted frame', function()
  local model = assert(kinematics.load({ robot = 'op3' }))
  local vp = assert(pipeline.new(vision('white'), ccfg, model))
  local cm = project.camera(W, H, ccfg.fovy)
  local q = {}
  for i = 1, #model.joints do q[i] = 0 end
  q[2] = -0.3                   -- the head tilted down: balls from 0.8 to 3.5 m in view
  local pose = model:camera_pose(q, { 0, 0 })
  it('finds it within 10% of its range and 2 degrees', function()
    for _, b in ipairs({ { 0.8, 0.1 }, { 1.5, -0.3 }, { 2.5, 0.4 }, { 3.5, 0.2 } }) do
      local u, v, depth = project.to_image(cm, pose, b[1], b[2], 0.07)
      local r = cm.f * 0.07 / depth
      local buf = ffi.new('uint8_t[?]', W * H * 2)
      for y = 0, H - 1 do
        for x = 0, W - 1 do
          local Y, U, V = 93, 98, 90
          local dx, dy = x + 0.5 - u, y + 0.5 - v
          if dx * dx + dy * dy <= r * r then
            -- white with dark patches, lit from above as the sim lights it (Platforms/Sim/render.cpp)
            local nz = math.sqrt(math.max(0, 1 - (dx * dx + dy * dy) / (r * r)))
            Y, U, V = math.floor(232 * (0.45 + 0.55 * math.max(0, -dy / r * 0.93 + nz * 0.3))), 128, 128
            local a, d = math.atan2(dy, dx), math.sqrt(dx * dx + dy * dy) / r
            if (d < 0.3) or (d > 0.55 and d < 0.85 and math.floor((a + math.pi) / (2 * math.pi) * 5 + 0.5) % 5 == 0
                             and math.abs(((a + math.pi) / (2 * math.pi) * 5 + 0.5) % 1 - 0.5) < 0.2) then
              Y = 40
            end
          end
          local p = (y * W + x) * 2
          buf[p] = Y
          buf[p + 1] = x % 2 == 0 and U or V
        end
      end
      local frame = { yuyv = buf, width = W, height = H }
      local det = vp:detect(frame, pose)
      local rng = math.sqrt(b[1] ^ 2 + b[2] ^ 2)
      local rj = require('Vision.detect_white').reject
      assert.is_true(det.ball.detected, string.format('ball at %.1f, %.1f: %s %g %g', b[1], b[2], rj.why, rj.a, rj.b))
      assert.is_true(math.abs(det.ball.range - rng) <= 0.1 * rng)
      local e = math.abs(math.atan2(det.ball.y, det.ball.x) - math.atan2(b[2], b[1]))
      assert.is_true(e <= math.rad(2))
      assert.is_true(det.ball.score >= 0.5 and det.ball.kind == 1)
    end
  end)
end)
