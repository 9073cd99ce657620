-- Lockstep participation: lets a process hold the simulated clock until it has done its work.
--
-- Protocol (block `sync`, the DCM side is in Platforms/Sim): a participant claims a slot with its
-- pid. The DCM publishes dcm.sensor for tick N, sets sync.tick = N, and then waits until every
-- live participant whose wake_tick <= N reports done_tick >= N; only then does it read
-- dcm.actuator and step. A participant that needs every tick (motion) sets wake_tick = N + 1
-- after each tick; one that needs few (a script in wait(), vision between frames) sets it further
-- ahead. When the DCM is not in lockstep mode, all of this is harmless and nobody waits.
--
-- Order within a tick (sync.observer holds a participant's stage): stage 0 (motion, vision) works on
-- the tick as soon as it is published; a participant of a higher stage first settles (waits for every
-- participant of a lower stage due at the tick), so the behavior (stage 1) reads what motion and vision
-- made of the tick, and a script or the recorder (stage 2, observers) reads what everybody made of it.
-- Without that order the behavior would read this tick's detections or the last ones, whoever ran
-- first, and a run (or a replay of it) would not be reproducible.
local ffi = require('ffi')
local shm = require('shm')

ffi.cdef [[ int getpid(void); ]]

local M = {}
local C = shm.C

local Participant = {}
Participant.__index = Participant

M.STAGE = { process = 0, after = 1, observer = 2 }

-- Claims a slot; errors if all are taken by live processes. opts.observer: a script that acts
-- between ticks; opts.after: a process that reads the others' output of the tick (the behavior);
-- see Participant:settle.
function M.join(opts)
  local observer = opts and (opts.observer and M.STAGE.observer or opts.after and M.STAGE.after) or M.STAGE.process
  local sync = shm.open('sync')
  local pid = ffi.C.getpid()
  local n = sync:count('pid')
  local pids = ffi.cast('volatile int32_t *', sync.pid)
  for pass = 1, 2 do
    for i = 0, n - 1 do
      local p = pids[i]
      if p == pid then return M._setup(sync, i) end
      -- a slot is taken in two steps: its pid negated (claimed: nobody else writes the slot, and the
      -- DCM does not count it yet) while its fields are set, then the pid itself. A process that wrote
      -- the fields before owning the slot could reset the progress of the one that won it (its
      -- done_tick back to 0 after it had finished the tick: the DCM would wait for it for ever)
      if (p == 0 or (pass == 2 and C.shm_pid_alive(math.abs(p)) == 0))
         and C.shm_cas_i32(pids + i, p, -pid) == 1 then
        -- "not done with anything yet": from the moment the DCM sees this pid it waits for our first
        -- done() at its first tick > 0, so it cannot run ahead of us
        sync.done_tick[i] = 0
        sync.wake_tick[i] = 0
        sync.observer[i] = observer
        assert(C.shm_cas_i32(pids + i, -pid, pid) == 1, 'lockstep: a claimed slot was taken away')
        return M._setup(sync, i)
      end
    end
  end
  error('lockstep: all ' .. n .. ' participant slots are taken', 2)
end

function M._setup(sync, slot)
  -- A DCM held for its first participants (--lockstep-wait N) publishes its first tick only once N
  -- have joined: wait for it, so that everybody's first work lands on that tick whoever came first
  -- (and each stage finds the lower ones there).
  if sync.lockstep[0] == 1 then
    local deadline = C.shm_now() + 60.0
    local word = ffi.cast('volatile uint32_t *', sync.tick)
    while word[0] < 1 and C.shm_now() < deadline do C.shm_futex_wait(word, word[0], 0.01) end
  end
  return setmetatable({ sync = sync, slot = slot }, Participant)
end

-- True while the DCM runs in lockstep mode.
function M.active()
  return shm.open('sync').lockstep[0] == 1
end

-- Reports tick `tick` done and asks to be consulted again at `wake_tick` (default tick + 1).
function Participant:done(tick, wake_tick)
  local s, i = self.sync, self.slot
  s.wake_tick[i] = wake_tick or (tick + 1)
  s.done_tick[i] = tick
  C.shm_fetch_add_u32(s.done_count, 1)
  C.shm_futex_wake(s.done_count)
end

-- True when the DCM waits for this participant at `tick`: its wake_tick has come and it has not
-- reported the tick. Usually that is the wake it asked for in done(); but a DCM that starts after
-- the process's last done() (the process was quicker, or the DCM restarted) consults every
-- participant from its own first tick on (Modules/dcm/lockstep.c), and a process that waited for
-- its own later wake would hold that DCM for ever.
function Participant:due(tick)
  local s, i = self.sync, self.slot
  return s.lockstep[0] == 1 and s.wake_tick[i] <= tick and s.done_tick[i] < tick
end

-- A participant of stage > 0 at tick `tick` (a script, the behavior): waits until every other live
-- participant of a lower stage that is due at this tick has finished it, so that what it reads is
-- that tick's outcome and what it writes is seen by the lower stages on the next tick, whoever runs
-- faster: a scenario then runs the same every time. Participants of one stage never wait for each
-- other; one that is stopped (SIGSTOP, a debugger) is not waited for (the DCM passes it over too:
-- Modules/dcm/lockstep.c); gives up after `timeout` s of wall time (default 5) on a participant that
-- stopped answering otherwise.
function Participant:settle(tick, timeout)
  local s, me = self.sync, self.slot
  if s.lockstep[0] ~= 1 then return end
  local deadline = C.shm_now() + (timeout or 5.0)
  local word = ffi.cast('volatile uint32_t *', s.done_count)
  local pid = ffi.cast('volatile int32_t *', s.pid)
  local wake = ffi.cast('volatile uint32_t *', s.wake_tick)
  local done = ffi.cast('volatile uint32_t *', s.done_tick)
  local stage = s.observer[me]
  if stage == 0 then return end
  while C.shm_now() < deadline do
    local seen = word[0]
    local waiting = false
    for i = 0, s:count('pid') - 1 do
      local p = pid[i]
      if i ~= me and p > 0 and s.observer[i] < stage and wake[i] <= tick and done[i] < tick
         and C.shm_pid_alive(p) == 1 and C.shm_pid_stopped(p) == 0 then
        waiting = true
        break
      end
    end
    if not waiting then return end
    C.shm_futex_wait(word, seen, 0.01)
  end
end

-- Gives the slot back (the DCM stops waiting for this process).
function Participant:leave()
  local s, i = self.sync, self.slot
  s.wake_tick[i] = 0xffffffff
  C.shm_cas_i32(ffi.cast('volatile int32_t *', s.pid) + i, ffi.C.getpid(), 0)
  C.shm_fetch_add_u32(s.done_count, 1)
  C.shm_futex_wake(s.done_count)
end

return M
