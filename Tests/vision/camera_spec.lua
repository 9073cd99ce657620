-- luacheck: std +busted
-- Lib/camera.lua: the dummy driver publishes into camera.image; the sim driver reads it.
local ffi = require('ffi')
local camera = require('camera')
local shm = require('shm')

ffi.cdef [[ int memcmp(const void *a, const void *b, size_t n); ]]

local robot = tonumber(os.getenv('ROBOT_ID') or '9001')

describe('camera', function()
  teardown(function()
    shm.unlink('camera.image', robot)
    shm.unlink('dcm.sensor', robot)
  end)

  it('refuses an unknown driver and a bad size', function()
    local cam, err = camera.open({ driver = 'bogus', width = 640, height = 480 })
    assert.is_nil(cam)
    assert.truthy(err:find('bogus'))
    cam, err = camera.open({ driver = 'dummy', width = 641, height = 480, robot_id = -1 })
    assert.is_nil(cam)
    assert.truthy(err:find('641'))
  end)

  it('dummy: random frames, in order, published to camera.image', function()
    local cam = assert(camera.open({ driver = 'dummy', width = 640, height = 480, fps = 0, seed = 7,
                                     robot_id = robot }))
    local img = shm.open('camera.image', { robot = robot })
    local last = 0
    local first_bytes = {}
    for i = 1, 5 do
      local f = assert(cam:grab(1.0))
      assert.are.equal(640, f.width); assert.are.equal(480, f.height)
      assert.is_true(f.seq > last); last = f.seq
      assert.are.equal(f.seq, img.frame[0])
      assert.are.equal(640, img.width[0])
      assert.are.equal(0, ffi.C.memcmp(f.yuyv, img.yuyv, 640 * 480 * 2))
      first_bytes[i] = f.yuyv[1000]
    end
    -- frames differ from one another (random)
    local distinct = {}
    for _, b in ipairs(first_bytes) do distinct[b] = true end
    local nd = 0
    for _ in pairs(distinct) do nd = nd + 1 end
    assert.is_true(nd >= 3)
    assert.are.equal(5, cam:stats().frames)
    cam:close()
  end)

  it('sim: reads the frames a DCM writes into camera.image', function()
    local img = shm.open('camera.image', { robot = robot })
    local sensor = shm.open('dcm.sensor', { robot = robot })
    local cam = assert(camera.open({ driver = 'sim', width = 640, height = 480, robot_id = robot }))
    -- no new frame and no DCM alive: reported as absent, not a crash
    img:write(function(b) b.frame[0] = 0 end)
    local f, err, code = cam:grab(0.05)
    assert.is_nil(f)
    assert.are.equal(camera.ENODEV, code)
    assert.truthy(err:find('sim'))
    -- act as the DCM: write a frame
    sensor.dcm_pid[0] = 0   -- no DCM alive
    img:write(function(b)
      b.width[0], b.height[0] = 640, 480
      b.time[0] = 12.5
      b.head[0], b.head[1] = 0.1, -0.2
      for i = 0, 640 * 480 * 2 - 1, 97 do b.yuyv[i] = i % 251 end
      b.frame[0] = 42
    end)
    f = assert(cam:grab(0.5))
    assert.are.equal(42, f.seq)
    assert.are.equal(12.5, f.time)
    assert.are.equal(0.1, f.head[0]); assert.are.equal(-0.2, f.head[1])
    assert.are.equal(0, ffi.C.memcmp(f.yuyv, img.yuyv, 640 * 480 * 2))
    -- the same frame is not delivered twice
    f = cam:grab(0.05)
    assert.is_nil(f)
    -- an invalid size is reported, not copied
    img:write(function(b) b.width[0] = 4000; b.height[0] = 4000; b.frame[0] = 43 end)
    f, err, code = cam:grab(0.5)
    assert.is_nil(f)
    assert.are.equal(camera.EFORMAT, code)
    assert.truthy(err:find('4000x4000'))
    cam:close()
  end)
end)
