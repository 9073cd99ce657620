-- Reads the frame files build/bin/sim_ball_frames writes (the format is in its header comment).
--
--   local frames = require('Tools.ball_train.frames')
--   local file = assert(frames.open('/tmp/frames.bin'))
--   for fr in file:each() do ... fr.yuyv, fr.cm, fr.pose, fr.ball.u/v/radius/distance/bearing/visible,
--                              fr.robots[i].x/y/u/v/visible/team end (team: the sim's, 1 or 2)
-- The frame's tables and its YUYV buffer are reused from one frame to the next.
local ffi = require('ffi')

local M = {}

local File = {}
File.__index = File

function M.open(path)
  local f, err = io.open(path, 'rb')
  if not f then return nil, err end
  local head = f:read(24)
  if not head or #head < 24 or head:sub(1, 8) ~= 'HRPBFRM1' then
    f:close()
    return nil, path .. ': not a sim_ball_frames file'
  end
  local ints = ffi.new('int32_t[4]')
  ffi.copy(ints, head:sub(9), 16)
  local self = setmetatable({ f = f, path = path, width = ints[0], height = ints[1], count = ints[2],
                              others = ints[3] }, File)
  self.yuyv = ffi.new('uint8_t[?]', self.width * self.height * 2)
  self.d = ffi.new('double[32]')
  self.i = ffi.new('int32_t[1]')
  self.frame = { yuyv = self.yuyv, width = self.width, height = self.height, ball = {}, robots = {},
                 pose = { 0, 0, 0, R = {}, height = 0 }, cm = {} }
  return self
end

function File:doubles(n)
  local s = self.f:read(8 * n)
  if not s or #s < 8 * n then error(self.path .. ': truncated', 2) end
  ffi.copy(self.d, s, 8 * n)
  return self.d
end

function File:int()
  local s = self.f:read(4)
  if not s or #s < 4 then error(self.path .. ': truncated', 2) end
  ffi.copy(self.i, s, 4)
  return self.i[0]
end

-- The next frame, or nil at the end.
function File:next()
  if (self.k or 0) >= self.count then return nil end
  self.k = (self.k or 0) + 1
  local fr = self.frame
  local d = self:doubles(15)
  fr.cm.f, fr.cm.cx, fr.cm.cy, fr.cm.width, fr.cm.height = d[0], d[1], d[2], self.width, self.height
  fr.pose[1], fr.pose[2] = d[3], d[4]
  for i = 1, 9 do fr.pose.R[i] = d[4 + i] end
  fr.pose.height = d[14]
  fr.pose[3] = d[14]
  d = self:doubles(6)
  local b = fr.ball
  b.u, b.v, b.radius, b.distance, b.bearing, b.visible = d[0], d[1], d[2], d[3], d[4], d[5]
  local n = self:int()
  for i = 1, n do
    d = self:doubles(6)
    fr.robots[i] = fr.robots[i] or {}
    local r = fr.robots[i]
    r.x, r.y, r.u, r.v, r.visible, r.team = d[0], d[1], d[2], d[3], d[4], d[5]
  end
  for i = n + 1, #fr.robots do fr.robots[i] = nil end
  local img = self.f:read(self.width * self.height * 2)
  if not img or #img < self.width * self.height * 2 then error(self.path .. ': truncated', 2) end
  ffi.copy(self.yuyv, img, #img)
  fr.index = self.k
  return fr
end

function File:each() return function() return self:next() end end

function File:close() self.f:close() end

return M
