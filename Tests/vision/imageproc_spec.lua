-- luacheck: std +busted
-- Lib/imageproc.lua: LUT from colour boxes, LUT files, the pipeline on a synthetic frame.
local ffi = require('ffi')
local imageproc = require('imageproc')

local colors = {
  { name = 'orange', bit = 1, y = { 40, 235 }, u = { 0, 112 }, v = { 168, 255 } },
  { name = 'green', bit = 8, y = { 30, 190 }, u = { 56, 124 }, v = { 40, 122 } },
}

-- A W x H YUYV frame filled with one colour, with a disc of another at (cx, cy) radius r.
local function frame(W, H, bg, fg, cx, cy, r)
  local buf = ffi.new('uint8_t[?]', W * H * 2)
  for y = 0, H - 1 do
    for x = 0, W - 1, 2 do
      local c = bg
      if (x - cx) ^ 2 + (y - cy) ^ 2 <= r * r then c = fg end
      local p = (y * W + x) * 2
      buf[p], buf[p + 1], buf[p + 2], buf[p + 3] = c[1], c[2], c[1], c[3]
    end
  end
  return buf
end

describe('imageproc', function()
  it('labels YUV values by the colour boxes', function()
    local lut = imageproc.lut_from_colors(colors)
    assert.are.equal(1, imageproc.classify(lut, 147, 45, 205))   -- orange
    assert.are.equal(8, imageproc.classify(lut, 99, 95, 86))     -- green
    assert.are.equal(0, imageproc.classify(lut, 240, 128, 128))  -- white: no class here
  end)

  it('refuses a malformed colour box naming the colour', function()
    assert.has_error(function()
      imageproc.lut_from_colors({ { name = 'pink', bit = 2, y = { 10, 5 }, u = { 0, 1 }, v = { 0, 1 } } })
    end, "colour 'pink': y must be {min, max} within 0..255")
  end)

  it('saves and loads a LUT; a corrupt one fails naming the file', function()
    local lut = imageproc.lut_from_colors(colors)
    local path = os.tmpname()
    assert.is_true(imageproc.save_lut(path, lut))
    local back = assert(imageproc.load_lut(path))
    assert.are.equal(0, ffi.C.memcmp(lut, back, imageproc.LUT_SIZE))
    local f = io.open(path, 'r+b'); f:seek('set', 5000); f:write('\255\254'); f:close()
    local res, err = imageproc.load_lut(path)
    assert.is_nil(res)
    assert.truthy(err:find(path, 1, true) and err:find('corrupt'))
    f = io.open(path, 'wb'); f:write(string.rep('x', 1000)); f:close()
    res, err = imageproc.load_lut(path)
    assert.is_nil(res)
    assert.truthy(err:find(path, 1, true))
    os.remove(path)
  end)

  it('finds an orange disc on green: centroid, area, block image', function()
    local W, H = 640, 480
    local buf = frame(W, H, { 99, 95, 86 }, { 147, 45, 205 }, 301, 201, 30)
    local p = imageproc.pipeline({ width = W, height = H, scale = 2, block = 4,
                                   lut = imageproc.lut_from_colors(colors) })
    p:process(buf)
    assert.are.equal(320, p.wa); assert.are.equal(240, p.ha)
    assert.are.equal(80, p.wb); assert.are.equal(60, p.hb)
    local n, regs = p:regions(1, 4)
    assert.are.equal(1, n)
    -- disc of radius 15 label pixels centred near (150.5, 100.5)
    assert.is_true(math.abs(regs[0].cx - 150.5) < 0.6 and math.abs(regs[0].cy - 100.5) < 0.6)
    assert.is_true(math.abs(regs[0].area - math.pi * 15 * 15) < 0.08 * math.pi * 15 * 15)
    -- green surrounds it
    local below = p:color_stats(8, regs[0].xmin, regs[0].xmax, regs[0].ymax + 1, regs[0].ymax + 10)
    assert.are.equal((regs[0].xmax - regs[0].xmin + 1) * 10, below.area)
    -- (the region array is reused by the next call)
    local nb, bregs = p:regions(1, 4, true)
    assert.are.equal(1, nb)
    assert.is_true(bregs[0].xmin >= 33 and bregs[0].xmax <= 42)
    assert.are.equal(p.wa * p.ha, p:count(9))
  end)

  it('refuses bad pipeline options', function()
    local lut = imageproc.new_lut()
    assert.has_error(function() imageproc.pipeline({ width = 641, height = 480, lut = lut }) end)
    assert.has_error(function() imageproc.pipeline({ width = 640, height = 480, scale = 3, lut = lut }) end)
  end)
end)
