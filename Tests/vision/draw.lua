-- Draws a frame with what the vision found into a PPM (RGB) file, for looking at:
-- the field boundary (yellow), the ball candidates (blue, with the classifier's probability as the
-- circle's brightness), the ball detected (red circle), the truth (green cross), robots seen (magenta box).
--   require('Tests.vision.draw').frame('out.ppm', frame, vp, det, truth_ball)
local ffi = require('ffi')

local M = {}

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
  end
  if det.ball.detected then
    circle(det.ball.u, det.ball.v, det.ball.radius, 255, 0, 0)
    circle(det.ball.u, det.ball.v, det.ball.radius + 1, 255, 0, 0)
  end
  for i = 1, (det.robots and det.robots.n or 0) do
    local r = det.robots[i]
    for x = r.u0, r.u1 do px(x, r.v0, 255, 0, 255); px(x, r.v1, 255, 0, 255) end
    for y = r.v0, r.v1 do px(r.u0, y, 255, 0, 255); px(r.u1, y, 255, 0, 255) end
  end
  local f = assert(io.open(path, 'wb'))
  f:write(string.format('P6\n%d %d\n255\n', w, h), ffi.string(buf, w * h * 3))
  f:close()
end

return M
