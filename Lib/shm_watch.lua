-- Shm blocks replaced under a running process: removed, or recreated (with another layout, say)
-- while the process keeps its old mapping, so nobody writes what it reads and nobody reads what it
-- writes. Every block of the robot (ROBOT_ID, or opts.robot) the process opened through shm.open is
-- looked at, once per `period` s of
-- wall time (a check is one shm_open and fstat a block; the robot's clock may have stopped with its
-- DCM, the wall clock has not).
--
--   local watch = require('shm_watch')
--   local check = watch.exit_on_replaced('vision')   -- a robot process, in its loop: check()
--     on a replacement: "vision: shm block(s) world replaced under this process (removed or
--     recreated): exiting for a restart" on stderr, exit status 3; run_main starts it afresh
--   local check = watch.reopen_replaced(log)          -- a supervisor reading through its block
--     tables (Run/main.lua): re-maps the replaced blocks in place and logs their names
local shm = require('shm')

local M = { EXIT_STATUS = 3, PERIOD = 1.0 }

-- A check that calls on_replaced(blocks) when blocks of the robot were replaced, at most every
-- opts.period s.
local function every(opts, on_replaced)
  local period, robot = opts.period or M.PERIOD, opts.robot or shm.robot_id()
  local next_check = shm.C.shm_now() + period
  return function()
    local now = shm.C.shm_now()
    if now < next_check then return end
    next_check = now + period
    local blocks = {}
    for _, b in ipairs(shm.replaced()) do
      if b._robot == robot then blocks[#blocks + 1] = b end
    end
    if #blocks > 0 then on_replaced(blocks) end
  end
end

-- Exits the process (status 3) naming the replaced blocks; opts.period (s, default 1), opts.robot,
-- opts.exit (tests: called with the message instead of exiting).
function M.exit_on_replaced(who, opts)
  opts = opts or {}
  return every(opts, function(blocks)
    local names = {}
    for i, b in ipairs(blocks) do names[i] = b:name() end
    local msg = string.format('%s: shm block(s) %s replaced under this process (removed or recreated): ' ..
      'exiting for a restart', who, table.concat(names, ', '))
    if opts.exit then return opts.exit(msg) end
    io.stderr:write(msg, '\n')
    io.stderr:flush()
    os.exit(M.EXIT_STATUS)
  end)
end

-- Re-maps the replaced blocks in place (Block:reopen) and logs each: log(fmt, ...).
function M.reopen_replaced(log, opts)
  opts = opts or {}
  return every(opts, function(blocks)
    for _, b in ipairs(blocks) do
      local ok, err = b:reopen()
      if ok then log('shm block %s was replaced: mapped again', b:name())
      else log('shm block %s was replaced and cannot be mapped again: %s', b:name(), err) end
    end
  end)
end

return M
