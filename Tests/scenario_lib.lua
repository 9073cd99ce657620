-- What the scenario scripts run by ./run_repl in the sim's lockstep share: numbered TAP lines,
-- "# " figure lines, waiting on a condition in robot time, a bisection search, and counting who
-- takes part in the lockstep.
--   local sc = require('Tests.scenario_lib').new(wait, Body)
--   local tap, note, wait_until = sc.tap, sc.note, sc.wait_until
local M = {}

-- wait: the REPL's wait(seconds) (lets the robot's clock run); Body: Lib/Body's table (get_time).
function M.new(wait, Body)
  local s = { count = 0 }
  -- prints "ok N - msg" or "not ok N - msg"; returns ok
  function s.tap(ok, msg)
    s.count = s.count + 1
    print(string.format('%s %d - %s', ok and 'ok' or 'not ok', s.count, msg))
    io.stdout:flush()
    return ok
  end
  function s.note(fmt, ...) print('# ' .. string.format(fmt, ...)) io.stdout:flush() end
  -- waits in steps of `step` (default 0.05 s) of robot time until pred() is true; true, or pred()'s last answer
  function s.wait_until(pred, timeout, step)
    local t0 = Body.get_time()
    while Body.get_time() - t0 < timeout do
      if pred() then return true end
      wait(step or 0.05)
    end
    return pred()
  end
  return s
end

-- The largest value in [lo, hi] for which ok(value) holds, by n halvings (ok true at lo, false at
-- hi, once between): the last value that held and the last that failed.
function M.bisect(lo, hi, n, ok)
  for _ = 1, n do
    local mid = 0.5 * (lo + hi)
    if ok(mid) then lo = mid else hi = mid end
  end
  return lo, hi
end

-- How many processes take part in the lockstep of `sync` (an open sync block): its live pids.
function M.participants(sync)
  local shm = require('shm')
  local n = 0
  for i = 0, sync:count('pid') - 1 do
    if sync.pid[i] > 0 and shm.C.shm_pid_alive(sync.pid[i]) == 1 then n = n + 1 end
  end
  return n
end

return M
