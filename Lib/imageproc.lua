-- The colour lookup-table pipeline (Modules/imageproc, libhrpimg) from LuaJIT.
--
--   local imageproc = require('imageproc')
--   local lut = assert(imageproc.load_lut('Config/site/venue.lut'))  -- or imageproc.lut_from_colors(colors)
--   local p = imageproc.pipeline{ width = 640, height = 480, scale = 2, block = 4, lut = lut }
--   p:process(frame.yuyv)           -- labels (p.labels, p.wa x p.ha), blocks (p.blocks, p.wb x p.hb)
--   local n, regs = p:regions(1, 4)       -- regions of colour bit 1 in the label image, largest first
--   regs[0].area, regs[0].cx, regs[0].xmin ...  (0-based cdata array, reused by the next call)
--   local st = p:color_stats(8, x0, x1, y0, y1)   -- statistics of colour bit 8 in a rectangle
-- Nothing on the per-frame path allocates: results live in buffers owned by the pipeline.
local ffi = require('ffi')
local native = require('native')

native.cdef('imageproc')   -- Modules/imageproc/imageproc.h

local C = native.load('img')

local M = { C = C, LUT_SIZE = 262144 }

local errbuf = ffi.new('char[512]')
local lut_t = ffi.typeof('uint8_t[262144]')
local region_arr_t = ffi.typeof('img_region[?]')

-- A zeroed LUT (cdata uint8_t[262144]).
function M.new_lut() return lut_t() end

-- Reads a LUT file. nil, err (naming the file) if it is missing, the wrong size or corrupt.
function M.load_lut(path)
  if type(path) ~= 'string' then error('imageproc.load_lut: path must be a string', 2) end
  local lut = lut_t()
  if C.img_lut_load(path, lut, errbuf, 512) < 0 then return nil, ffi.string(errbuf) end
  return lut
end

-- Writes a LUT file. true, or nil, err.
function M.save_lut(path, lut)
  if C.img_lut_save(path, lut, errbuf, 512) < 0 then return nil, ffi.string(errbuf) end
  return true
end

local function check_range(name, key, r)
  if type(r) ~= 'table' or type(r[1]) ~= 'number' or type(r[2]) ~= 'number' or r[1] < 0 or r[2] > 255
      or r[1] > r[2] then
    error(string.format("colour '%s': %s must be {min, max} within 0..255", name, key), 3)
  end
end

-- ORs colour boxes into lut (new LUT if nil). colors: list of
-- { name = 'orange', bit = 1, y = {min, max}, u = {min, max}, v = {min, max} }
function M.add_colors(lut, colors)
  lut = lut or lut_t()
  local n = #colors
  local ranges = ffi.new('img_color_range[?]', math.max(n, 1))
  for i, c in ipairs(colors) do
    local name = tostring(c.name)
    if type(c.bit) ~= 'number' or c.bit < 1 or c.bit > 255 then
      error(string.format("colour '%s': bit must be 1..255", name), 2)
    end
    check_range(name, 'y', c.y); check_range(name, 'u', c.u); check_range(name, 'v', c.v)
    local r = ranges[i - 1]
    r.bit = c.bit
    r.ymin, r.ymax, r.umin, r.umax, r.vmin, r.vmax = c.y[1], c.y[2], c.u[1], c.u[2], c.v[1], c.v[2]
  end
  if C.img_lut_add_ranges(lut, ranges, n) < 0 then error('imageproc.add_colors: invalid range', 2) end
  return lut
end

-- A LUT built from the colour boxes alone.
function M.lut_from_colors(colors) return M.add_colors(nil, colors) end

-- The LUT entry (label) of one YUV value.
function M.classify(lut, y, u, v)
  return lut[bit.bor(bit.lshift(bit.rshift(y, 2), 12), bit.lshift(bit.rshift(u, 2), 6), bit.rshift(v, 2))]
end

local Pipeline = {}
Pipeline.__index = Pipeline

-- A pipeline for frames of width x height: label image subsampled by scale, block image of
-- block x block label pixels. opts: width, height, scale (2), block (4), lut, maxregions (16).
function M.pipeline(opts)
  if type(opts) ~= 'table' then error('imageproc.pipeline: options table expected', 2) end
  local w, h = opts.width, opts.height
  local scale, bs = opts.scale or 2, opts.block or 4
  if type(w) ~= 'number' or type(h) ~= 'number' or w <= 0 or h <= 0 or w % 2 ~= 0 then
    error('imageproc.pipeline: width (even) and height required', 2)
  end
  if scale < 2 or scale % 2 ~= 0 then error('imageproc.pipeline: scale must be even, >= 2', 2) end
  if opts.lut == nil then error('imageproc.pipeline: lut required', 2) end
  local wa, ha = math.floor(w / scale), math.floor(h / scale)
  local wb, hb = math.ceil(wa / bs), math.ceil(ha / bs)
  local maxn = opts.maxregions or 16
  local cc = C.img_cc_new(wa, ha)
  if cc == nil then error('imageproc.pipeline: out of memory', 2) end
  local self = setmetatable({
    width = w, height = h, scale = scale, block = bs, lut = opts.lut,
    wa = wa, ha = ha, wb = wb, hb = hb,
    labels = ffi.new('uint8_t[?]', wa * ha),
    blocks = ffi.new('uint8_t[?]', wb * hb),
    cc = ffi.gc(cc, C.img_cc_free),
    maxregions = maxn,
    out = region_arr_t(maxn),
    stats = region_arr_t(1),
  }, Pipeline)
  return self
end

-- Labels a YUYV frame (pointer to width*height*2 bytes) and builds the block image.
function Pipeline:process(yuyv)
  C.img_label_yuyv(yuyv, self.width, self.height, self.lut, self.scale, self.labels)
  C.img_block_or(self.labels, self.wa, self.ha, self.block, self.blocks)
end

-- Connected regions of colour mask; on the block image if blocks is true. Returns the number
-- found and the pipeline's region array (0-based, the largest min(found, maxn) first).
function Pipeline:regions(mask, maxn, blocks)
  maxn = math.min(maxn or self.maxregions, self.maxregions)
  local n
  if blocks then
    n = C.img_regions(self.cc, self.blocks, self.wb, self.hb, mask, self.out, maxn)
  else
    n = C.img_regions(self.cc, self.labels, self.wa, self.ha, mask, self.out, maxn)
  end
  return n, self.out
end

-- Statistics of colour mask in the rectangle [x0, x1] x [y0, y1] of the label image (of the
-- block image if blocks is true). Returns an img_region (reused by the next call).
function Pipeline:color_stats(mask, x0, x1, y0, y1, blocks)
  local r = self.stats
  if blocks then
    C.img_color_stats(self.blocks, self.wb, self.hb, mask, x0, x1, y0, y1, r)
  else
    C.img_color_stats(self.labels, self.wa, self.ha, mask, x0, x1, y0, y1, r)
  end
  return r[0]
end

-- Pixels of colour mask in the whole label image.
function Pipeline:count(mask)
  return C.img_count(self.labels, self.wa, self.ha, mask)
end

return M
