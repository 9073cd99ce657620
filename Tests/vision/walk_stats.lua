-- The figures of the walking-vision scorer (walk_eye.lua): recall, false detections, and the range
-- and bearing errors of several estimates of the same detections (the vision's own and re-projections
-- of its pixel through other camera poses).
--
--   local st = require('Tests.vision.walk_stats').new({ 'vision', 'upright', ... })
--   st:count(reason)                         a frame not scored, and why
--   st:empty(detected)                       a frame with no part of the ball in view
--   local ok, note = st:ball(range, tx, ty, detected, est)   a frame with the ball fully in view;
--       est[name] = { x, y } (robot frame) per estimate; the first name's decides found / wrong
--   st:report(); st:tap(gate, { min_inview = N })
--   st:save(path); local all = M.merge({ path1, path2 })   -- the runs of several seeds as one
local M = {}
local S = {}
S.__index = S

function M.new(names)
  return setmetatable({ names = names, why = {}, inview = 0, found = 0, wrong = 0, nempty = 0, false_pos = 0,
    range = {}, bearing = {}, by_dist = {} }, S)
end

function S:count(reason) self.why[reason] = (self.why[reason] or 0) + 1 end

function S:skipped()
  local keys = {}
  for k in pairs(self.why) do keys[#keys + 1] = k end
  table.sort(keys)
  local out = {}
  for _, k in ipairs(keys) do out[#out + 1] = string.format('%s %d', k, self.why[k]) end
  return #out > 0 and table.concat(out, ', ') or 'none'
end

function S:empty(detected)
  self.nempty = self.nempty + 1
  if detected then self.false_pos = self.false_pos + 1 end
end

local function bearing_err(x, y, tx, ty)
  local e = math.abs(math.atan2(y, x) - math.atan2(ty, tx))
  if e > math.pi then e = 2 * math.pi - e end
  return math.deg(e)
end

function S:ball(range, tx, ty, detected, est)
  self.inview = self.inview + 1
  local band = math.min(4, math.floor(range) + 1)    -- 0-1, 1-2, 2-3, 3-4 m
  local bd = self.by_dist[band] or { n = 0, found = 0 }
  self.by_dist[band] = bd
  bd.n = bd.n + 1
  local main = est[self.names[1]]
  if not detected or not main or not main[1] then return false, 'MISSED' end
  local ex, ey = main[1], main[2]
  if math.sqrt((ex - tx) ^ 2 + (ey - ty) ^ 2) > math.max(0.25, 0.25 * range) then
    self.wrong = self.wrong + 1
    return false, string.format('WRONG place: detected at %.2f, %.2f', ex, ey)
  end
  self.found = self.found + 1
  bd.found = bd.found + 1
  local parts = {}
  for _, name in ipairs(self.names) do
    local p = est[name]
    if p and p[1] then
      local r = math.sqrt(p[1] ^ 2 + p[2] ^ 2)
      local re = (r - range) / range
      if range <= 3 then
        self.range[name] = self.range[name] or {}
        table.insert(self.range[name], math.abs(re))
      end
      self.bearing[name] = self.bearing[name] or {}
      table.insert(self.bearing[name], bearing_err(p[1], p[2], tx, ty))
      parts[#parts + 1] = string.format('%s %+.1f%%', name, 100 * re)
    end
  end
  return true, string.format('found: bearing error %.2f deg, range error %s', bearing_err(ex, ey, tx, ty),
    table.concat(parts, ', '))
end

local function summary(list)
  if not list or #list == 0 then return { n = 0, mean = 0, p95 = 0, max = 0 } end
  local s = {}
  local sum = 0
  for i, v in ipairs(list) do s[i] = v; sum = sum + v end
  table.sort(s)
  return { n = #s, mean = sum / #s, p95 = s[math.max(1, math.ceil(0.95 * #s))], max = s[#s] }
end

function S:report()
  print(string.format('%s ball, walking: recall %d/%d = %.1f%% (fully in view, 0.3-4 m; '
    .. '%d detected at a wrong place), false detections %d/%d frames without the ball = %.2f%%',
    self.kind or 'the', self.found, self.inview, 100 * self.found / math.max(1, self.inview), self.wrong,
    self.false_pos, self.nempty,
    100 * self.false_pos / math.max(1, self.nempty)))
  local bands = {}
  for b = 1, 4 do
    local bd = self.by_dist[b]
    if bd then bands[#bands + 1] = string.format('%d-%d m %d/%d', b - 1, b, bd.found, bd.n) end
  end
  print('recall by range: ' .. table.concat(bands, ', '))
  print('range error up to 3 m (mean, p95, max) and bearing error (mean, p95, max), per camera pose:')
  for _, name in ipairs(self.names) do
    local r, b = summary(self.range[name]), summary(self.bearing[name])
    print(string.format('  %-9s range %5.1f%% %5.1f%% %5.1f%% (%d)   bearing %.2f %.2f %.2f deg', name,
      100 * r.mean, 100 * r.p95, 100 * r.max, r.n, b.mean, b.p95, b.max))
  end
end

-- TAP lines: enough frames in view (always gated), and the goals named in `gate` (the others print)
function S:tap(gate, opts)
  local n = 0
  local function tap(ok, text)
    n = n + 1
    print((ok and 'ok ' or 'not ok ') .. n .. ' - ' .. text)
  end
  local function goal(name, ok, text)
    if gate:find(name, 1, true) then tap(ok, text) else print('# ' .. text .. (ok and '' or ' (not met)')) end
  end
  local recall = self.found / math.max(1, self.inview)
  local fp = self.false_pos / math.max(1, self.nempty)
  local r, b = summary(self.range[self.names[1]]), summary(self.bearing[self.names[1]])
  tap(self.inview >= opts.min_inview, string.format('frames with the ball fully in view: %d >= %d', self.inview,
    opts.min_inview))
  goal('recall', recall >= 0.95, string.format('recall %.1f%% >= 95%%', 100 * recall))
  goal('false', fp <= 0.01, string.format('false detections %.2f%% <= 1%%', 100 * fp))
  goal('range', r.n > 0 and r.max <= 0.10, string.format('range error max %.1f%% <= 10%% up to 3 m', 100 * r.max))
  goal('bearing', b.n > 0 and b.max <= 3, string.format('bearing error max %.2f deg <= 3', b.max))
  print('1..' .. n)
end

-- Writes the figures gathered as a Lua table (for merge).
function S:save(path)
  local f = assert(io.open(path, 'w'))
  local function put(v, indent)
    if type(v) == 'table' then
      f:write('{\n')
      for k, x in pairs(v) do
        f:write(indent, '  [', type(k) == 'string' and string.format('%q', k) or tostring(k), '] = ')
        put(x, indent .. '  ')
        f:write(',\n')
      end
      f:write(indent, '}')
    elseif type(v) == 'number' then f:write(string.format('%.17g', v))
    else f:write(string.format('%q', tostring(v))) end
  end
  f:write('return ')
  put({ kind = self.kind, names = self.names, why = self.why, inview = self.inview, found = self.found,
        wrong = self.wrong,
        nempty = self.nempty, false_pos = self.false_pos, range = self.range, bearing = self.bearing,
        by_dist = self.by_dist }, '')
  f:write('\n')
  f:close()
end

-- The figures of several saved runs together.
function M.merge(paths)
  local all
  for _, path in ipairs(paths) do
    local d = assert(loadfile(path))()
    if not all then
      all = M.new(d.names)
      all.kind = d.kind
    end
    for k, n in pairs(d.why) do all.why[k] = (all.why[k] or 0) + n end
    for _, k in ipairs({ 'inview', 'found', 'wrong', 'nempty', 'false_pos' }) do all[k] = all[k] + d[k] end
    for _, k in ipairs({ 'range', 'bearing' }) do
      for name, list in pairs(d[k]) do
        all[k][name] = all[k][name] or {}
        for _, v in ipairs(list) do table.insert(all[k][name], v) end
      end
    end
    for b, bd in pairs(d.by_dist) do
      local a = all.by_dist[b] or { n = 0, found = 0 }
      a.n, a.found = a.n + bd.n, a.found + bd.found
      all.by_dist[b] = a
    end
  end
  return all
end

return M
