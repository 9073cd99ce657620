-- The soak's memory check (Tests/soak/soak.sh): does a process's resident memory grow on, or did it
-- only reach a few high-water marks?
--   luajit Tests/soak/rss_check.lua SOAK_OUT WARMUP_S DCM_KB_PER_S LUA_KB_PER_S [STEPS]
-- reads the "proc NAME t=T pid=.. rss_kb=.." lines of Tests/soak/soak_play.lua and prints, per process,
-- "ok - ..." or "not ok - ..." with its series, its rate and its steps.
--
-- What is measured: the high-water mark of RSS (its running maximum) from the first sample at or after the
-- warm-up to the end. A leak raises it in every interval, at its rate. What is not a leak raises it a few
-- times and then stays: a buffer grown to the largest frame or blur seen so far, an allocator arena, a
-- thread's stack, the JIT's traces; a garbage collector's sawtooth does not raise it once its peak is
-- reached. So the high-water's rises are sorted, the STEPS (default 2) largest are set aside as one-time
-- steps, and the rest of its growth over the measured span is the rate (KB per simulated second), which
-- must stay within the bound: DCM_KB_PER_S for the DCM (native code: flat once warm), LUA_KB_PER_S for
-- the LuaJIT processes (their heap's high-water still creeps for a while, the garbage collector's peaks
-- and the JIT's traces). A leak of R KB/s over a span of S s with samples every I s shows as at least
-- R * (S - STEPS * I) / S KB/s (600 s soak: 1 KB/s shows as 0.85 KB/s).
local M = {}

-- series: { {t=, kb=}, ... } in time order (after the warm-up); steps: how many rises are set aside.
-- Returns rate (KB/s), the rises set aside ({ {t0=, t1=, kb=}, ... }, largest first), the high-water's
-- whole growth (KB) and the span (s).
function M.rate(series, steps)
  steps = steps or 2
  if #series < 2 then return 0, {}, 0, 0 end
  local rises, hw = {}, series[1].kb
  for i = 2, #series do
    local h = math.max(hw, series[i].kb)
    if h > hw then rises[#rises + 1] = { t0 = series[i - 1].t, t1 = series[i].t, kb = h - hw } end
    hw = h
  end
  local growth = hw - series[1].kb
  table.sort(rises, function(a, b) return a.kb > b.kb or (a.kb == b.kb and a.t1 < b.t1) end)
  local set_aside, rest = {}, growth
  for i = 1, math.min(steps, #rises) do
    set_aside[i] = rises[i]
    rest = rest - rises[i].kb
  end
  local span = series[#series].t - series[1].t
  return span > 0 and rest / span or 0, set_aside, growth, span
end

-- Parses soak_play.lua's output: { [name] = { pid = first pid, pids = n distinct, all = { {t=, kb=}... } } }
-- and the names in order of first appearance.
function M.parse(lines)
  local procs, order = {}, {}
  for line in lines do
    local name, t, pid, kb = line:match('^proc (%S+) t=([%d.]+) pid=(%d+) rss_kb=(%-?%d+)')
    if name then
      local p = procs[name]
      if not p then
        p = { pid = pid, pids = { [pid] = true }, npids = 1, all = {} }
        procs[name] = p
        order[#order + 1] = name
      elseif not p.pids[pid] then
        p.pids[pid] = true
        p.npids = p.npids + 1
      end
      p.all[#p.all + 1] = { t = tonumber(t), kb = tonumber(kb) }
    end
  end
  return procs, order
end

-- One process's verdict: ok (boolean) and its line.
function M.judge(name, all, warm, bound, steps)
  steps = steps or 2
  local series = {}
  for _, s in ipairs(all) do
    if s.t >= warm - 1e-6 then series[#series + 1] = s end
  end
  local parts = {}
  for _, s in ipairs(all) do
    parts[#parts + 1] = (s.t >= warm - 1e-6 and '' or '(') .. s.kb .. (s.t >= warm - 1e-6 and '' or ')')
  end
  if #series < 4 then
    return false, string.format('%s: too few samples after the %.0f s warm-up (%d): %s', name, warm, #series,
      table.concat(parts, ' '))
  end
  local rate, aside, growth, span = M.rate(series, steps)
  local st = {}
  for _, r in ipairs(aside) do st[#st + 1] = string.format('+%d KB at t=%.0f-%.0f', r.kb, r.t0, r.t1) end
  local ok = rate <= bound
  return ok, string.format('%s: RSS high-water after the %.0f s warm-up grows %.2f KB/s without its %d largest ' ..
    'steps (bound %.2f KB/s; %d KB in %.0f s in all; steps: %s); RSS KB every %.0f s (warm-up in brackets): %s',
    name, warm, rate, steps, bound, growth, span, #st > 0 and table.concat(st, ', ') or 'none',
    #all > 1 and all[2].t - all[1].t or 0, table.concat(parts, ' '))
end

if arg and arg[0] and arg[0]:match('rss_check%.lua$') then
  local file, warm, dcm_bound, lua_bound, steps = arg[1], tonumber(arg[2]), tonumber(arg[3]), tonumber(arg[4]),
    tonumber(arg[5] or 2)
  assert(file and warm and dcm_bound and lua_bound and steps,
    'usage: rss_check.lua SOAK_OUT WARMUP_S DCM_KB_PER_S LUA_KB_PER_S [STEPS]')
  local f = assert(io.open(file))
  local procs, order = M.parse(f:lines())
  f:close()
  if #order == 0 then print('not ok - no process sampled (see ' .. file .. ')') end
  for _, name in ipairs(order) do
    local p = procs[name]
    local ok, line = M.judge(name, p.all, warm, name == 'dcm' and dcm_bound or lua_bound, steps)
    if p.npids > 1 then
      ok, line = false, line .. string.format(' (%d different pids: restarted)', p.npids)
    end
    print((ok and 'ok - ' or 'not ok - ') .. line)
  end
end

return M
