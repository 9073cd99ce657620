-- luacheck: std +busted
-- Lib/lockstep.lua's slot claim: a slot is written only by the process that owns it, so a process
-- joining beside another never resets the other's progress (the DCM would then wait for a tick the
-- other had finished, for ever).
local ffi = require('ffi')
local shm = require('shm')
local lockstep = require('lockstep')

ffi.cdef [[ int getpid(void); int fork(void); void _exit(int); int waitpid(int, int *, int); ]]

local sync = shm.open('sync')
local pids = ffi.cast('volatile int32_t *', sync.pid)
local n = sync:count('pid')

local function clear()
  for i = 0, n - 1 do
    pids[i] = 0
    sync.done_tick[i], sync.wake_tick[i], sync.observer[i] = 0, 0, 0
  end
  sync.lockstep[0] = 0
end

-- a pid that is certainly dead: a child that exited and was reaped
local function dead_pid()
  local child = ffi.C.fork()
  if child == 0 then ffi.C._exit(0) end
  ffi.C.waitpid(child, nil, 0)
  return child
end

describe('lockstep.join', function()
  before_each(clear)
  after_each(clear)

  it('takes a free slot with its fields set before the DCM can count it', function()
    sync.done_tick[0], sync.wake_tick[0], sync.observer[0] = 77, 0xffffffff, 5
    local p = lockstep.join({ observer = true })
    assert.equal(0, p.slot)
    assert.equal(ffi.C.getpid(), pids[0])
    assert.equal(0, sync.done_tick[0])
    assert.equal(0, sync.wake_tick[0])
    assert.equal(lockstep.STAGE.observer, sync.observer[0])
  end)

  it('never writes into a slot another live process is claiming', function()
    -- slot 0 claimed (negative pid) by a live process that has set its fields and finished a tick
    local other = 1   -- init: alive
    pids[0] = -other
    sync.done_tick[0], sync.wake_tick[0], sync.observer[0] = 41, 42, 0
    local p = lockstep.join({ observer = true })
    assert.equal(1, p.slot)
    assert.equal(-other, pids[0])
    assert.equal(41, sync.done_tick[0])
    assert.equal(42, sync.wake_tick[0])
    assert.equal(0, sync.observer[0])
  end)

  it('never writes into a slot another live process owns, on either pass', function()
    for i = 0, n - 1 do pids[i] = 1; sync.done_tick[i] = 9 end   -- pid 1 (init) is alive
    assert.has_error(function() lockstep.join() end)
    for i = 0, n - 1 do assert.equal(9, sync.done_tick[i]) end
  end)

  it('takes over the slot, or the claim, of a process that died', function()
    for i = 0, n - 1 do pids[i] = 1 end
    pids[3] = -dead_pid()
    local p = lockstep.join()
    assert.equal(3, p.slot)
    assert.equal(ffi.C.getpid(), pids[3])
    pids[3] = dead_pid()
    sync.done_tick[3] = 50
    p = lockstep.join()
    assert.equal(3, p.slot)
    assert.equal(0, sync.done_tick[3])
  end)
end)
