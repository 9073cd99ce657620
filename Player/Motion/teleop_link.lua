-- The `teleop` and `teleop.chunk` shm blocks between Lib/Teleop.lua (the operator's side: a checked
-- trajectory in chunks, commands, a heartbeat) and the motion state teleop
-- (Player/Motion/states/teleop.lua).
-- Before a tick: a new chunk is taken into the trajectory being received (in order; a chunk out of
-- order, an angle that is not finite, beyond its joint's limits or a step faster than the validator
-- allows, or a size that does not fit the body drops the trajectory with the reason, whoever sent
-- it), and a trajectory whose samples have all arrived and whose checksum matches is ctl.teleop_rx
-- with whole = true; a new command goes into ctl.teleop_cmd; the heartbeat's age into
-- ctl.teleop_link_ok. After it: the executor's state (ctl.teleop_report) is written back.
local ffi = require('ffi')
local teleop = require('teleop')

local M = {}
local Link = {}
Link.__index = Link

local CHUNK = 2048    -- Config/shm.schema: nteleop_chunk
local NSEG = 16       -- Config/shm.schema: nteleop_seg
local MAX_SAMPLES = 200 * 120   -- two minutes at 200 Hz: a longer trajectory is refused

-- The bounds every sample that arrives is held to, whoever sent it: the joints' limits and the
-- step one period allows at the validator's share of each actuator's speed (robot: the robot config).
function M.bounds(robot)
  local Config = require('Config')
  local copts = { robot = robot.name }
  local actuators = Config.load('actuators', nil, copts)
  local share = Config.load('teleop', nil, copts).check.speed_share
  local b = { lo = {}, hi = {}, step = {} }
  for i, j in ipairs(robot.joints) do
    b.lo[i], b.hi[i] = robot.limits[j][1], robot.limits[j][2]
    local act = actuators[robot.actuator[j]]
    -- a hair over the validator's bound: its samples pass whatever their rounding
    b.step[i] = (act and act.speed or 1.0) * share * robot.period * (1 + 1e-6) + 1e-9
  end
  return b
end

-- block: teleop, chunks: teleop.chunk; link_timeout: s without a heartbeat before the link counts as
-- lost; bounds: M.bounds(robot).
function M.new(block, chunks, link_timeout, bounds)
  local self = setmetatable({ b = block, cb = chunks, chunk = chunks.chunk_seq[0], cmd = block.cmd_seq[0],
    bounds = bounds,
    beat = block.heartbeat[0], beat_t = nil, timeout = link_timeout, reason = '', written_reason = nil }, Link)
  self.writer = function(x) self:write(x) end
  return self
end

-- Drops trajectory `id` (a start naming it is refused with why).
local function drop(self, ctl, id, why)
  self.rx = nil
  ctl.teleop_rx = nil
  ctl.teleop_dropped = { id = id, why = why }
  self.dropped_id = id
  self.reason = why
end

-- Takes the chunk in block x (inside its read lock).
local function take_chunk(self, ctl, x)
  local id, n, nj = x.traj_id[0], x.traj_n[0], x.traj_nj[0]
  if id == self.dropped_id then return end   -- the rest of a dropped trajectory: taken, not kept
  local rx = self.rx
  if not rx or rx.id ~= id then
    if nj ~= ctl.n then
      return drop(self, ctl, id, string.format('trajectory %d: %d angles per sample, the body has %d', id, nj, ctl.n))
    end
    if n < 1 or n > MAX_SAMPLES then
      return drop(self, ctl, id, string.format('trajectory %d: %d samples (1..%d)', id, n, MAX_SAMPLES))
    end
    local nseg = x.traj_nseg[0]
    if nseg < 1 or nseg > NSEG then
      return drop(self, ctl, id, string.format('trajectory %d: %d segments (1..%d)', id, nseg, NSEG))
    end
    rx = { id = id, n = n, nj = nj, checksum = x.traj_checksum[0], segments = {}, q = {}, received = 0,
      hash = teleop.FNV_START, whole = false }
    for s = 1, nseg do rx.segments[s] = x.traj_seg[s - 1] end
    if rx.segments[nseg] ~= n then
      return drop(self, ctl, id, string.format('trajectory %d: its last segment ends at sample %d, not %d', id,
        rx.segments[nseg], n))
    end
    self.rx = rx
    ctl.teleop_rx = rx
  end
  if rx.whole then return end
  local first, cn = x.chunk_first[0], x.chunk_n[0]
  if first ~= rx.received then
    return drop(self, ctl, id, string.format('trajectory %d: a chunk from sample %d, expected %d (a chunk lost)', id,
      first + 1, rx.received + 1))
  end
  if cn < 1 or cn * nj > CHUNK or first + cn > n then
    return drop(self, ctl, id, string.format('trajectory %d: a chunk of %d samples from sample %d does not fit', id,
      cn, first + 1))
  end
  local h, fnv = rx.hash, teleop.fnv1a
  local lo, hi, step = self.bounds.lo, self.bounds.hi, self.bounds.step
  local names = ctl.robot.joints
  for k = 0, cn - 1 do
    local s = {}
    local before = rx.q[first + k]
    for j = 1, nj do
      local a = x.chunk[k * nj + j - 1]
      if a ~= a or a == math.huge or a == -math.huge then
        return drop(self, ctl, id, string.format('trajectory %d: sample %d, %s is not a finite angle', id,
          first + k + 1, names[j]))
      end
      if a < lo[j] or a > hi[j] then
        return drop(self, ctl, id, string.format('trajectory %d: sample %d, %s at %.3f rad beyond %.3f .. %.3f', id,
          first + k + 1, names[j], a, lo[j], hi[j]))
      end
      if before and math.abs(a - before[j]) > step[j] then
        return drop(self, ctl, id, string.format('trajectory %d: sample %d, %s steps %.4f rad in a period (at most '
          .. '%.4f)', id, first + k + 1, names[j], math.abs(a - before[j]), step[j]))
      end
      s[j] = a
      h = fnv(h, a)
    end
    rx.q[first + k + 1] = s
  end
  rx.hash = h
  rx.received = first + cn
  if rx.received == n then
    if h ~= rx.checksum then
      return drop(self, ctl, id, string.format('trajectory %d: checksum %08x, sent %08x: refused', id,
        h % 2 ^ 32, rx.checksum % 2 ^ 32))
    end
    rx.whole = true
  end
end

function Link:before(ctl)
  local b = self.b
  local t = ctl.t
  local beat = b.heartbeat[0]
  if beat ~= self.beat then
    self.beat, self.beat_t = beat, t
  end
  ctl.teleop_link_ok = self.beat_t ~= nil and t - self.beat_t <= self.timeout
  local cb = self.cb
  local seq = cb.chunk_seq[0]
  if seq ~= self.chunk then
    self.chunk = seq
    cb:read(function(x) take_chunk(self, ctl, x) end)
    self.ack = seq
  end
  seq = b.cmd_seq[0]
  if seq ~= self.cmd then
    self.cmd = seq
    local cmd, id = b.cmd[0], b.cmd_id[0]
    if ctl:state() == 'teleop' then
      ctl.teleop_cmd = { seq = seq, cmd = cmd, id = id }
    else
      ctl.teleop_done = { seq = seq, ok = false, error = "the teleop motion is not running (Motion.request('teleop'))" }
    end
  end
end

local STATE = { idle = 0, loading = 1, ready = 2, running = 3, paused = 4, stopped = 5, held = 6, done = 7 }
M.STATE = STATE

function Link:write(x)
  local r, rx = self.r, self.rx
  if self.ack then x.chunk_ack[0] = self.ack end
  local done = self.done
  if done then
    x.cmd_done[0] = done.seq
    x.cmd_rc[0] = done.ok and 0 or -1
    if not done.ok then self.reason = done.error end
  end
  x.tick[0] = self.tick
  x.link_ok[0] = self.link_ok and 1 or 0
  x.received[0] = rx and rx.received or 0
  x.loaded_id[0] = rx and rx.whole and rx.id or 0
  local state = r and r.state or 'idle'
  if state == 'idle' and rx then state = rx.whole and 'ready' or 'loading' end
  x.state[0] = STATE[state]
  x.sample[0] = r and r.sample or 0
  x.segment[0] = r and r.segment or 0
  -- the latest event's reason: the link's (a trajectory dropped, a command refused) or the state's
  if r and r.reason ~= '' and r.reason ~= self.state_reason then self.reason = r.reason end
  self.state_reason = r and r.reason
  local reason = self.reason
  if reason ~= self.written_reason then
    ffi.fill(x.reason, 256)
    ffi.copy(x.reason, reason, math.min(#reason, 255))
    self.written_reason = reason
  end
end

-- Written while the state runs, and when there is something to answer or a change of what is
-- reported (a chunk taken, the link's state, a reason): the recorder keeps a block when it changes.
function Link:after(ctl, tick)
  if ctl.teleop_reason then
    self.reason = ctl.teleop_reason
    ctl.teleop_reason = nil
  end
  local r, done = ctl.teleop_report, ctl.teleop_done
  local link_ok = ctl.teleop_link_ok
  if not (r or self.r or done or self.ack or link_ok ~= self.link_ok or self.reason ~= self.written_reason) then
    return
  end
  self.r, self.tick, self.link_ok = r, tick, link_ok
  self.done = done
  ctl.teleop_done = nil
  self.b:write(self.writer)
  self.ack = nil
end

return M
