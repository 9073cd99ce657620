-- Teleoperation's executor from the REPL and the operator's server: a trajectory checked by
-- Lib/teleop.lua sent in chunks to the motion state teleop (Player/Motion/states/teleop.lua), the
-- commands, the heartbeat and the executor's state, through the `teleop` and `teleop.chunk` blocks.
--
--   Motion.request('teleop')
--   local plan = assert(require('teleop').validator():plan(q0, { kp }))
--   local id = Teleop.send(plan, wait)    -- one chunk per motion tick; wait(s) lets the clock run
--   Teleop.heartbeat()                    -- the operator's link is alive (at least every link_timeout s)
--   Teleop.start(id); Teleop.pause(); Teleop.resume(); Teleop.stop()   -- each returns its sequence number
--   p(Teleop.status())  --> { state = 'running', sample = 212, segment = 1, loaded = id, received = n,
--                       --     link_ok = true, reason = '', last = { seq, ok, error } }
-- States: idle, loading (chunks arriving), ready (arrived whole, checksum right), running, paused,
-- stopped, held (the link was lost), done.
local ffi = require('ffi')
local shm = require('shm')

local M = {}

M.STATES = { [0] = 'idle', 'loading', 'ready', 'running', 'paused', 'stopped', 'held', 'done' }
M.CMD = { start = 1, pause = 2, resume = 3, stop = 4 }
local CHUNK = 2048   -- Config/shm.schema: nteleop_chunk
local NSEG = 16

local block = shm.lazy('teleop')
local chunks = shm.lazy('teleop.chunk')

-- Sends a plan's samples ({ q, n, nj, segments, checksum }); wait(s) is called between chunks until
-- the executor took each (the REPL's wait: lockstep-aware). opts.corrupt = k changes one angle of chunk k
-- after the checksum (a test of the executor's check). Returns the trajectory's id.
function M.send(plan, wait, opts)
  opts = opts or {}
  if type(wait) ~= 'function' then error('Teleop.send(plan, wait): wait(s) lets the clock run', 2) end
  if #plan.segments > NSEG then
    error(string.format('Teleop.send: %d segments, at most %d', #plan.segments, NSEG), 2)
  end
  local b, ack = chunks(), block()
  local per = math.floor(CHUNK / plan.nj)
  local id
  b:write(function(x)
    id = x.traj_id[0] + 1
    x.traj_id[0], x.traj_n[0], x.traj_nj[0], x.traj_checksum[0] = id, plan.n, plan.nj, plan.checksum
    x.traj_nseg[0] = #plan.segments
    for s, last in ipairs(plan.segments) do x.traj_seg[s - 1] = last end
  end)
  local first, k = 0, 0
  while first < plan.n do
    k = k + 1
    local cn = math.min(per, plan.n - first)
    local seq
    b:write(function(x)
      x.chunk_first[0], x.chunk_n[0] = first, cn
      for s = 0, cn - 1 do
        local q = plan.q[first + s + 1]
        for j = 1, plan.nj do x.chunk[s * plan.nj + j - 1] = q[j] end
      end
      if opts.corrupt == k then x.chunk[0] = x.chunk[0] + 1e-3 end
      seq = x.chunk_seq[0] + 1
      x.chunk_seq[0] = seq
    end)
    local tries = 0
    while ack.chunk_ack[0] ~= seq do
      tries = tries + 1
      if tries > 2000 then error('Teleop.send: the motion process takes no chunks (is it running?)', 2) end
      wait(0.005)
    end
    first = first + cn
  end
  return id
end

local function command(name, id)
  local seq
  block():write(function(x)
    x.cmd[0] = M.CMD[name]
    if id then x.cmd_id[0] = id end
    seq = x.cmd_seq[0] + 1
    x.cmd_seq[0] = seq
  end)
  return seq
end

function M.start(id)
  if type(id) ~= 'number' then error('Teleop.start(id): the id Teleop.send returned', 2) end
  return command('start', id)
end
function M.pause() return command('pause') end
function M.resume() return command('resume') end
function M.stop() return command('stop') end

function M.heartbeat()
  local b = block()
  b:write(function(x) x.heartbeat[0] = x.heartbeat[0] + 1 end)
end

function M.status()
  return block():read(function(x)
    local s = { state = M.STATES[x.state[0]], sample = x.sample[0], segment = x.segment[0], loaded = x.loaded_id[0],
      received = x.received[0], link_ok = x.link_ok[0] == 1, reason = ffi.string(x.reason), tick = x.tick[0],
      last = { seq = x.cmd_done[0], ok = x.cmd_rc[0] == 0 } }
    if not s.last.ok then s.last.error = s.reason end
    return s
  end)
end

return M
