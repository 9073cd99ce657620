-- Keyframe motions: joint-space frames with durations and hardness, interpolated.
--
-- A keyframe file is Config/robots/<ROBOT>/keyframes/<name>.lua returning
--   { frames = { { duration = s, hardness = h | {njoint}, q = {njoint rad} }, ... } }
-- (q in the robot's joint order, Config/robots/<ROBOT>/robot.lua). Each frame is reached from the
-- previous one (the first from the pose the motion starts in) over its duration, with a smooth
-- (zero-velocity at both ends) profile. A file with a wrong joint count, a missing or mistyped
-- field fails at load with the file and the frame named.
local native = require('native')
local Config = require('Config')

local M = {}

local cache = {}

local function finite(x) return type(x) == 'number' and x == x and x ~= math.huge and x ~= -math.huge end

-- Checks a keyframe table (from `file`) for njoint joints; returns it or raises naming the file.
function M.check(kf, file, njoint)
  local function fail(fmt, ...) error(file .. ': ' .. string.format(fmt, ...), 0) end
  if type(kf) ~= 'table' then fail('must return a table') end
  local frames = rawget(kf, 'frames')
  if type(frames) ~= 'table' then fail("missing field 'frames' (a list of frames)") end
  if #frames == 0 then fail("'frames' is empty") end
  for i, f in ipairs(frames) do
    if type(f) ~= 'table' then fail('frame %d: must be a table', i) end
    if f.duration == nil then fail("frame %d: missing field 'duration'", i) end
    if not finite(f.duration) or f.duration <= 0 then fail("frame %d: 'duration' must be a number > 0", i) end
    if f.q == nil then fail("frame %d: missing field 'q'", i) end
    if type(f.q) ~= 'table' then fail("frame %d: 'q' must be a list of %d joint angles", i, njoint) end
    if #f.q ~= njoint then fail("frame %d: 'q' has %d joint angles, the robot has %d", i, #f.q, njoint) end
    for j = 1, njoint do
      if not finite(f.q[j]) then fail("frame %d: 'q[%d]' is not a finite number", i, j) end
    end
    local h = f.hardness
    if h == nil then fail("frame %d: missing field 'hardness'", i) end
    if type(h) == 'table' then
      if #h ~= njoint then fail("frame %d: 'hardness' has %d values, the robot has %d joints", i, #h, njoint) end
      for j = 1, njoint do
        if not finite(h[j]) or h[j] < 0 or h[j] > 1 then fail("frame %d: 'hardness[%d]' must be 0..1", i, j) end
      end
    elseif not finite(h) or h < 0 or h > 1 then
      fail("frame %d: 'hardness' must be 0..1 or a list of %d values", i, njoint)
    end
  end
  return kf
end

-- Loads (cached) Config/robots/<robot>/keyframes/<name>.lua for a robot of njoint joints.
function M.load(name, njoint, robot)
  robot = robot or Config.robot()
  local file = 'Config/robots/' .. robot .. '/keyframes/' .. name .. '.lua'
  if cache[file] then return cache[file] end
  local chunk, err = loadfile(native.root() .. '/' .. file)
  if not chunk then error(file .. ': ' .. tostring(err), 0) end
  local ok, res = pcall(chunk)
  if not ok then error(file .. ': ' .. tostring(res), 0) end
  local kf = M.check(res, file, njoint)
  kf.file = file
  cache[file] = kf
  return kf
end

function M.reload() cache = {} end

local Player = {}
Player.__index = Player

-- Starts playing keyframe motion kf at time t from joint angles q0 (1-based) and hardness h0
-- (a number or a list; the frames' hardness is reached with the same profile).
function M.play(kf, t, q0, h0)
  local n = #q0
  local p = setmetatable({ kf = kf, t0 = t, i = 1, n = n, from = {}, hfrom = {}, done = false }, Player)
  for j = 1, n do
    p.from[j] = q0[j]
    p.hfrom[j] = type(h0) == 'table' and h0[j] or (h0 or 1)
  end
  return p
end

local function smooth(s) return s * s * (3 - 2 * s) end

-- Writes the joint angles and hardness at time t into q and h (1-based); returns true when the
-- last frame has been reached.
function Player:update(t, q, h)
  local frames = self.kf.frames
  while true do
    local f = frames[self.i]
    local s = (t - self.t0) / f.duration
    if s < 1 or self.i == #frames then
      if s > 1 then s = 1 end
      if s < 0 then s = 0 end
      local a = smooth(s)
      local fh = f.hardness
      for j = 1, self.n do
        q[j] = self.from[j] + a * (f.q[j] - self.from[j])
        local hj = type(fh) == 'table' and fh[j] or fh
        h[j] = self.hfrom[j] + a * (hj - self.hfrom[j])
      end
      self.done = s >= 1 and self.i == #frames
      return self.done
    end
    -- next frame starts from this frame's target
    for j = 1, self.n do
      self.from[j] = f.q[j]
      self.hfrom[j] = type(f.hardness) == 'table' and f.hardness[j] or f.hardness
    end
    self.t0 = self.t0 + f.duration
    self.i = self.i + 1
  end
end

-- Total duration of a keyframe motion, s.
function M.duration(kf)
  local d = 0
  for _, f in ipairs(kf.frames) do d = d + f.duration end
  return d
end

return M
