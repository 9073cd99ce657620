-- Joint trajectory files: a motion generated ahead (Tools/pattern/gen_pattern.lua) and played back
-- by the motion state `pattern` (Player/Motion/states/pattern.lua). A text file, CSV with a header:
--
--   # hrp joint trajectory                  comment lines start with '#'
--   # robot hoap3                           '# key value' lines: robot (the body it was made for),
--   # dt 0.005                              dt (s between rows), joints (how many joint columns)
--   # joints 26
--   t,r_hip_yaw,r_hip_roll,...,zmp_x,zmp_y  the header: time (s), then `joints` joint names (rad),
--   0,0.0012,-0.0261,...,0.0001,0            then any other columns (planned ZMP, COM, feet: m)
--
-- The joint columns must be the body's joints (robot.joints), each once, in any order; times
-- start at 0 and increase; every value is a finite number. Errors name the file and its line.
--
--   local trajectory = require('trajectory')
--   local tr = trajectory.load(path, robot)  -- robot: Config robot table; error on a bad file
--   tr.t[k], tr.q[k][i] (rad, robot joint order), tr.extra[name][k], tr.columns, tr.meta, tr.duration
--   local k, a = tr:locate(t)                -- rows k and k + 1 around time t, weight a of row k + 1
--   tr:joints_at(t, q)                       -- joint angles at time t (linear), into q
--   trajectory.write(path, { robot = name, dt = s, joints = names, extra = names, rows = { {t, ...} },
--     comments = { line, ... } })
local M = {}

local function finite(x) return x == x and x ~= math.huge and x ~= -math.huge end

local function split(line)
  local out = {}
  for field in (line .. ','):gmatch('([^,]*),') do out[#out + 1] = field:match('^%s*(.-)%s*$') end
  return out
end

local Traj = {}
Traj.__index = Traj

-- Parses the text of a trajectory file; `name` names it in errors. robot: the body (joints).
function M.parse(text, name, robot)
  local meta, header, hline = {}, nil, nil
  local t, q, extra = {}, {}, {}
  local cols -- column -> joint index (robot order) or extra name
  local njoint = #robot.joints
  local body = {}
  for i, j in ipairs(robot.joints) do body[j] = i end
  local lineno = 0
  local function fail(fmt, ...) error(string.format('%s:%d: ' .. fmt, name, lineno, ...), 0) end
  for line in (text .. '\n'):gmatch('([^\n]*)\n') do
    lineno = lineno + 1
    line = line:gsub('\r$', '')
    if line:match('^%s*#') then
      local key, value = line:match('^%s*#%s*(%w+)%s+(%S+)%s*$')
      if key and header == nil then meta[key] = value end
    elseif not line:match('^%s*$') then
      if not header then
        header, hline = split(line), lineno
        local n = tonumber(meta.joints)
        if not n then fail("no '# joints N' line before the header") end
        if n ~= njoint then
          fail('%d joint columns, the body %s has %d joints', n, tostring(robot.name), njoint)
        end
        if header[1] ~= 't' then fail("the header's first column must be 't', got '%s'", tostring(header[1])) end
        if #header < 1 + n then fail('the header names %d columns, fewer than t and %d joints', #header, n) end
        cols = {}
        local seen = {}
        for c = 2, 1 + n do
          local j = header[c]
          local i = body[j]
          if not i then fail("column %d '%s' is not a joint of the body %s", c, j, tostring(robot.name)) end
          if seen[j] then fail("joint '%s' named twice", j) end
          seen[j], cols[c] = true, i
        end
        for c = 2 + n, #header do
          if header[c] == '' then fail('column %d has no name', c) end
          cols[c] = header[c]
          extra[header[c]] = {}
        end
      else
        local f = split(line)
        if #f ~= #header then fail('%d values, the header (line %d) names %d columns', #f, hline, #header) end
        local k = #t + 1
        local row = {}
        for c = 1, #f do
          local v = tonumber(f[c])
          if not v or not finite(v) then fail("column '%s': '%s' is not a finite number", header[c], f[c]) end
          if c == 1 then
            if (k == 1 and math.abs(v) > 1e-9) or (k > 1 and v <= t[k - 1]) then
              fail('times must start at 0 and increase (t = %s)', f[c])
            end
            t[k] = v
          elseif type(cols[c]) == 'number' then row[cols[c]] = v
          else extra[cols[c]][k] = v end
        end
        q[k] = row
      end
    end
  end
  if not header then error(string.format('%s: no header line (t, joint names, ...)', name), 0) end
  if #t < 1 then error(string.format('%s: no rows after the header (line %d)', name, hline), 0) end
  return setmetatable({ t = t, q = q, extra = extra, columns = header, meta = meta, duration = t[#t],
    n = njoint, file = name, last = 1 }, Traj)
end

-- Reads and parses a trajectory file (see M.parse).
function M.load(path, robot)
  local f, err = io.open(path, 'r')
  if not f then error(string.format('%s: cannot read the trajectory file (%s)', path, tostring(err)), 0) end
  local text = f:read('*a')
  f:close()
  return M.parse(text, path, robot)
end

-- Rows k and k + 1 around time t (clamped to the file's span) and the weight a of row k + 1.
function Traj:locate(t)
  local ts, n = self.t, #self.t
  if t <= 0 or n == 1 then return 1, 0 end
  if t >= ts[n] then return n, 0 end
  local k = self.last
  if ts[k] > t then k = 1 end
  while ts[k + 1] <= t do k = k + 1 end
  self.last = k
  return k, (t - ts[k]) / (ts[k + 1] - ts[k])
end

-- Joint angles at time t (linear between rows) into q (robot order); returns q.
function Traj:joints_at(t, q)
  local k, a = self:locate(t)
  local r0, r1 = self.q[k], self.q[k + 1] or self.q[k]
  for i = 1, self.n do q[i] = r0[i] + a * (r1[i] - r0[i]) end
  return q
end

-- A column of the other columns at time t (linear); nil when the file has no such column.
function Traj:extra_at(name, t)
  local col = self.extra[name]
  if not col then return nil end
  local k, a = self:locate(t)
  return col[k] + a * ((col[k + 1] or col[k]) - col[k])
end

-- Writes a trajectory file: spec = { robot, dt, joints = { names }, extra = { names },
-- rows = { { t, joint values..., extra values... } }, comments = { lines } }.
function M.write(path, spec)
  local f = assert(io.open(path, 'w'))
  f:write('# hrp joint trajectory (Lib/trajectory.lua)\n')
  for _, c in ipairs(spec.comments or {}) do f:write('# ', c, '\n') end
  f:write(string.format('# robot %s\n# dt %.9g\n# joints %d\n', spec.robot, spec.dt, #spec.joints))
  local head = { 't' }
  for _, j in ipairs(spec.joints) do head[#head + 1] = j end
  for _, e in ipairs(spec.extra or {}) do head[#head + 1] = e end
  f:write(table.concat(head, ','), '\n')
  local fmt = {}
  for _, row in ipairs(spec.rows) do
    assert(#row == #head, 'trajectory.write: a row has ' .. #row .. ' values, the header ' .. #head)
    for c = 1, #row do
      assert(finite(row[c]), 'trajectory.write: a value is not finite (column ' .. head[c] .. ')')
      fmt[c] = string.format(c == 1 and '%.4f' or '%.6f', row[c])
    end
    f:write(table.concat(fmt, ',', 1, #row), '\n')
  end
  f:close()
end

return M
