-- Draws a frame with what the vision found into a PNG (RGB; zlib through the FFI), for looking at:
-- the field boundary (yellow), the ball candidates (blue, with the classifier's probability as the
-- circle's brightness), the ball detected (red circle), the truth (green cross; with u0, v0 a green
-- line from where it was at the exposure's start), robots seen (boxes in
-- their team's colour: red, blue, magenta when unknown), the robots' truth (a green tick up from their middle
-- on the ground).
--   require('Tests.vision.draw').frame('out.png', frame, vp, det, truth_ball)
local ffi = require('ffi')

ffi.cdef [[
unsigned long compressBound(unsigned long sourceLen);
int compress2(uint8_t *dest, unsigned long *destLen, const uint8_t *source, unsigned long sourceLen, int level);
unsigned long crc32(unsigned long crc, const uint8_t *buf, unsigned int len);
]]
local zlib = ffi.load('z')

local M = {}

local function be32(n)
  return string.char(bit.band(bit.rshift(n, 24), 255), bit.band(bit.rshift(n, 16), 255),
                     bit.band(bit.rshift(n, 8), 255), bit.band(n, 255))
end

local function chunk(kind, data)
  local body = kind .. data
  local crc = tonumber(zlib.crc32(0, body, #body))
  return be32(#data) .. body .. be32(crc)
end

-- Writes w x h RGB pixels (cdata) as a PNG file.
function M.write_png(path, rgb, w, h)
  local raw = ffi.new('uint8_t[?]', (w * 3 + 1) * h)
  for y = 0, h - 1 do
    raw[y * (w * 3 + 1)] = 0                       -- filter: none
    ffi.copy(raw + y * (w * 3 + 1) + 1, rgb + y * w * 3, w * 3)
  end
  local n = ffi.new('unsigned long[1]', zlib.compressBound((w * 3 + 1) * h))
  local z = ffi.new('uint8_t[?]', n[0])
  assert(zlib.compress2(z, n, raw, (w * 3 + 1) * h, 6) == 0, 'zlib compress2 failed')
  local f = assert(io.open(path, 'wb'))
  f:write('\137PNG\r\n\26\n', chunk('IHDR', be32(w) .. be32(h) .. string.char(8, 2, 0, 0, 0)),
          chunk('IDAT', ffi.string(z, n[0])), chunk('IEND', ''))
  f:close()
end

local function rgb_of(yuyv, w, h)
  local buf = ffi.new('uint8_t[?]', w * h * 3)
  for i = 0, w * h - 1 do
    local pair = bit.band(i, bit.bnot(1)) * 2
    local y, u, v = yuyv[2 * i], yuyv[pair + 1] - 128, yuyv[pair + 3] - 128
    local r, g, b = y + 1.402 * v, y - 0.344 * u - 0.714 * v, y + 1.772 * u
    buf[3 * i] = math.max(0, math.min(255, r))
    buf[3 * i + 1] = math.max(0, math.min(255, g))
    buf[3 * i + 2] = math.max(0, math.min(255, b))
  end
  return buf
end

function M.frame(path, fr, vp, det, truth)
  local w, h = fr.width, fr.height
  local buf = rgb_of(fr.yuyv, w, h)
  local function px(x, y, r, g, b)
    x, y = math.floor(x), math.floor(y)
    if x < 0 or y < 0 or x >= w or y >= h then return end
    local o = 3 * (y * w + x)
    buf[o], buf[o + 1], buf[o + 2] = r, g, b
  end
  local function circle(cx, cy, rad, r, g, b)
    local n = math.max(24, math.floor(rad * 6))
    for k = 0, n - 1 do
      local a = 2 * math.pi * k / n
      px(cx + rad * math.cos(a), cy + rad * math.sin(a), r, g, b)
    end
  end
  local s = vp.p.scale
  if vp.bd then
    for x = 0, vp.p.wa - 1 do
      local t = vp.bd.top[x]
      if t < vp.p.ha then
        for dx = 0, s - 1 do px(x * s + dx, t * s, 255, 255, 0) end
      end
    end
  end
  if vp.bd and vp.bd.ncand then
    for i = 0, vp.bd.ncand - 1 do
      local c = vp.bd.cand[i]
      local k = c.prob >= 0 and c.prob or 0
      circle(c.u, c.v, c.radius + 2, 0, math.floor(80 + 175 * k), 255)
    end
  end
  if truth and truth.radius > 0 then
    for d = -6, 6 do px(truth.u + d, truth.v, 0, 255, 0); px(truth.u, truth.v + d, 0, 255, 0) end
    -- where the ball was seen at the exposure's start (a moving camera): a green line to the cross
    if truth.u0 then
      local n = math.ceil(math.max(math.abs(truth.u0 - truth.u), math.abs(truth.v0 - truth.v))) + 1
      for k = 0, n do
        px(truth.u0 + (truth.u - truth.u0) * k / n, truth.v0 + (truth.v - truth.v0) * k / n, 0, 255, 0)
      end
    end
  end
  if det.ball.detected then
    circle(det.ball.u, det.ball.v, det.ball.radius, 255, 0, 0)
    circle(det.ball.u, det.ball.v, det.ball.radius + 1, 255, 0, 0)
  end
  -- the robots' truth: a green tick up from the middle of their feet
  for _, r in ipairs(fr.robots or {}) do
    if r.visible > 0 then
      for d = 0, 20 do px(r.u, r.v - d, 0, 255, 0); px(r.u + 1, r.v - d, 0, 255, 0) end
    end
  end
  for i = 1, (det.robots and det.robots.n or 0) do
    local r = det.robots[i]
    local cr, cg, cb = 255, 0, 255
    if r.team == 1 then cr, cg, cb = 255, 40, 40 elseif r.team == 0 then cr, cg, cb = 40, 80, 255 end
    for k = 0, 1 do
      for x = r.u0, r.u1 do px(x, r.v0 + k, cr, cg, cb); px(x, r.v1 - k, cr, cg, cb) end
      for y = r.v0, r.v1 do px(r.u0 + k, y, cr, cg, cb); px(r.u1 - k, y, cr, cg, cb) end
    end
  end
  M.write_png(path, buf, w, h)
end

return M
