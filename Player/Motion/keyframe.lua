-- Keyframe motions: joint-space frames with durations and hardness, interpolated.
--
-- A keyframe file is Config/robots/<ROBOT>/keyframes/<name>.lua returning
--   { frames = { { duration = s, hardness = h | { joint = h, ... },
--                  q = { joint = rad, ... }, mirror = { l_joint = rad, ... } }, ... } }
-- Joints are named as in the body's robot.lua. `mirror` (optional) names left-side joints (l_...):
-- each also sets its right twin (r_...) to the mirror image of the pose through the body's
-- sagittal plane, its sign taken from the two joints' axes (r = -l on the OP3 and the DARwIn-OP);
-- a joint may be named once per frame, in `q` or through `mirror`. The motion drives exactly the
-- joints named in some frame; a joint a frame does not name holds where it is (the pose the motion
-- started from, then its last target), and so does its hardness. Each frame is reached from the
-- previous one (the first from the start pose) over its duration, with a smooth (zero-velocity at
-- both ends) profile. An unknown joint, a non-finite angle, a missing or mistyped field fails at
-- load naming the file, the frame and the joint.
local native = require('native')
local Config = require('Config')

local M = {}

local cache = {}

local function finite(x) return type(x) == 'number' and x == x and x ~= math.huge and x ~= -math.huge end

-- Checks a keyframe table (from `file`) against a body: { index = { name = 1-based index },
-- mirror = function(l_name) -> twin index, sign, twin name | nil, reason }. Returns the motion:
-- { file, joints = { driven indices, ascending }, frames = { { duration, q = { [i] = rad },
-- h = { [i] = hardness } }, ... } }, or raises naming the file, the frame and the joint.
function M.check(kf, file, body)
  local function fail(fmt, ...) error(file .. ': ' .. string.format(fmt, ...), 0) end
  if type(kf) ~= 'table' then fail('must return a table') end
  local frames = kf.frames
  if type(frames) ~= 'table' then fail("missing field 'frames' (a list of frames)") end
  if #frames == 0 then fail("'frames' is empty") end
  local index = body.index
  local out, driven = { file = file, frames = {} }, {}
  for k, f in ipairs(frames) do
    if type(f) ~= 'table' then fail('frame %d: must be a table', k) end
    for key in pairs(f) do
      if key ~= 'duration' and key ~= 'hardness' and key ~= 'q' and key ~= 'mirror' then
        fail("frame %d: unknown field '%s' (duration, hardness, q, mirror)", k, tostring(key))
      end
    end
    if f.duration == nil then fail("frame %d: missing field 'duration'", k) end
    if not finite(f.duration) or f.duration <= 0 then fail("frame %d: 'duration' must be a number > 0", k) end
    if f.q == nil and f.mirror == nil then fail("frame %d: missing field 'q' (joint = rad)", k) end
    local q, named = {}, {}
    local function put(i, name, rad, where)
      if named[i] then fail("frame %d: joint '%s' is named twice (%s and %s)", k, name, named[i], where) end
      named[i], q[i], driven[i] = where, rad, true
    end
    for _, field in ipairs({ 'q', 'mirror' }) do
      local t = f[field]
      if t ~= nil and type(t) ~= 'table' then fail("frame %d: '%s' must be a table of joint = rad", k, field) end
      for name, rad in pairs(t or {}) do
        local i = index[name]
        if not i then fail("frame %d: joint '%s' in '%s': the body has no such joint", k, tostring(name), field) end
        if not finite(rad) then fail("frame %d: joint '%s': the angle must be a finite number", k, name) end
        put(i, name, rad, "'" .. field .. "'")
        if field == 'mirror' then
          local ti, sign, twin = body.mirror(name)
          if not ti then fail("frame %d: joint '%s' in 'mirror': %s", k, name, sign) end
          put(ti, twin, sign * rad, "'mirror' of '" .. name .. "'")
        end
      end
    end
    local h = f.hardness
    local hh = {}
    if h == nil then fail("frame %d: missing field 'hardness'", k) end
    if type(h) == 'table' then
      for name, v in pairs(h) do
        local i = index[name]
        if not i then fail("frame %d: joint '%s' in 'hardness': the body has no such joint", k, tostring(name)) end
        if not finite(v) or v < 0 or v > 1 then fail("frame %d: joint '%s': 'hardness' must be 0..1", k, name) end
        hh[i], driven[i] = v, true
      end
    elseif not finite(h) or h < 0 or h > 1 then
      fail("frame %d: 'hardness' must be 0..1 or a table of joint = 0..1", k)
    else
      hh = h
    end
    out.frames[k] = { duration = f.duration, q = q, h = hh }
  end
  local joints = {}
  for i in pairs(driven) do joints[#joints + 1] = i end
  table.sort(joints)
  -- a number for the frame's hardness applies to every joint the motion drives
  for _, fr in ipairs(out.frames) do
    if type(fr.h) == 'number' then
      local v, hh = fr.h, {}
      for _, i in ipairs(joints) do hh[i] = v end
      fr.h = hh
    end
  end
  out.joints = joints
  return out
end

-- Loads (cached per body) Config/robots/<robot>/keyframes/<name>.lua for a body (see check); a
-- body without that file takes its base body's (robot.lua `base`).
function M.load(name, body, robot)
  robot = robot or Config.robot()
  local chain = Config.robot_chain(robot)
  local file
  for _, r in ipairs(chain) do
    file = 'Config/robots/' .. r .. '/keyframes/' .. name .. '.lua'
    local f = io.open(native.root() .. '/' .. file, 'r')
    if f then f:close() break end
  end
  local per_body = cache[body] or {}
  cache[body] = per_body
  if per_body[file] then return per_body[file] end
  local chunk, err = loadfile(native.root() .. '/' .. file)
  if not chunk then error(file .. ': ' .. tostring(err), 0) end
  local ok, res = pcall(chunk)
  if not ok then error(file .. ': ' .. tostring(res), 0) end
  local kf = M.check(res, file, body)
  per_body[file] = kf
  return kf
end

function M.reload() cache = setmetatable({}, { __mode = 'k' }) end
M.reload()

local Player = {}
Player.__index = Player

-- Starts playing keyframe motion kf at time t from the whole-body joint angles q0 and hardness h0
-- (1-based, robot order; h0 may be a number). Each frame's target for every driven joint is
-- resolved here (a joint a frame does not name keeps its previous target).
function M.play(kf, t, q0, h0)
  local joints = kf.joints
  local p = setmetatable({ kf = kf, t0 = t, i = 1, joints = joints, from = {}, hfrom = {}, done = false,
    q = {}, h = {} }, Player)
  local q, h = {}, {}
  for _, j in ipairs(joints) do
    p.from[j] = q0[j]
    p.hfrom[j] = type(h0) == 'table' and h0[j] or (h0 or 1)
    q[j], h[j] = p.from[j], p.hfrom[j]
  end
  for k, f in ipairs(kf.frames) do
    local fq, fh = {}, {}
    for _, j in ipairs(joints) do
      q[j] = f.q[j] or q[j]
      h[j] = f.h[j] or h[j]
      fq[j], fh[j] = q[j], h[j]
    end
    p.q[k], p.h[k] = fq, fh
  end
  return p
end

local function smooth(s) return s * s * (3 - 2 * s) end

-- Writes the driven joints' angles and hardness at time t into q and h (1-based, robot order; the
-- other joints are left alone); returns true when the last frame has been reached.
function Player:update(t, q, h)
  local frames = self.kf.frames
  local joints = self.joints
  while true do
    local f = frames[self.i]
    local s = (t - self.t0) / f.duration
    if s < 1 or self.i == #frames then
      if s > 1 then s = 1 end
      if s < 0 then s = 0 end
      local a = smooth(s)
      local fq, fh, from, hfrom = self.q[self.i], self.h[self.i], self.from, self.hfrom
      for _, j in ipairs(joints) do
        q[j] = from[j] + a * (fq[j] - from[j])
        h[j] = hfrom[j] + a * (fh[j] - hfrom[j])
      end
      self.done = s >= 1 and self.i == #frames
      return self.done
    end
    -- next frame starts from this frame's target
    local fq, fh = self.q[self.i], self.h[self.i]
    for _, j in ipairs(joints) do self.from[j], self.hfrom[j] = fq[j], fh[j] end
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
