-- Shared-memory tool for one robot (ROBOT_ID or --robot N):
--   Tools/shm/shm list                 the robot's blocks present in /dev/shm, with size and creator
--   Tools/shm/shm dump BLOCK [FIELD]   every field (or one) with its values
--   Tools/shm/shm set BLOCK FIELD V..  write values (one number fills every element)
--   Tools/shm/shm remove               remove all of the robot's blocks
-- Reads each segment's own field table, so it works on any block, declared or not.
local shm = require('shm')

local args = { ... }
local robot = shm.robot_id()
if args[1] == '--robot' then
  robot = tonumber(args[2]) or error('--robot needs a number')
  table.remove(args, 1) table.remove(args, 1)
end

local function usage()
  io.stderr:write('usage: Tools/shm/shm [--robot N] list | dump BLOCK [FIELD] | set BLOCK FIELD VALUE... | remove\n')
  os.exit(2)
end

local function robot_segments()
  local names = {}
  local p = io.popen('ls /dev/shm 2>/dev/null')
  local prefix = 'hrp.' .. robot .. '.'
  for f in p:lines() do
    if f:sub(1, #prefix) == prefix then names[#names + 1] = f:sub(#prefix + 1) end
  end
  p:close()
  table.sort(names)
  return names
end

local function open_raw(name)
  local b, err = shm.open(name, { robot = robot, raw = true, try = true })
  if not b then io.stderr:write(err, '\n') os.exit(1) end
  return b
end

local function format_values(b, field)
  local v = b:get(field)
  if type(v) ~= 'table' then return tostring(v) end
  if #v > 32 then
    local nonzero = 0
    for i = 1, #v do if v[i] ~= 0 then nonzero = nonzero + 1 end end
    return string.format('[%d elements, %d non-zero]', #v, nonzero)
  end
  local parts = {}
  for i = 1, #v do parts[i] = string.format('%.6g', v[i]) end
  return table.concat(parts, ' ')
end

local cmd = args[1]
if cmd == 'list' then
  local segs = robot_segments()
  if #segs == 0 then print('robot ' .. robot .. ': no blocks') end
  for _, name in ipairs(segs) do
    local b = shm.open(name, { robot = robot, raw = true, try = true })
    if b then
      print(string.format('%-16s %3d fields', name, #b:fields()))
    else
      print(string.format('%-16s (unreadable)', name))
    end
  end
elseif cmd == 'dump' then
  if not args[2] then usage() end
  local b = open_raw(args[2])
  for _, field in ipairs(b:fields()) do
    if not args[3] or args[3] == field then
      print(string.format('%-18s %-4s[%d]  %s', field, b:type(field), b:count(field), format_values(b, field)))
    end
  end
elseif cmd == 'set' then
  if not args[4] then usage() end
  local b = open_raw(args[2])
  local values = {}
  for i = 4, #args do
    values[#values + 1] = tonumber(args[i]) or error("not a number: '" .. args[i] .. "'")
  end
  b:write(function(blk) blk:set(args[3], #values == 1 and values[1] or values) end)
elseif cmd == 'remove' then
  local segs = robot_segments()
  for _, name in ipairs(segs) do shm.unlink(name, robot) end
  print(string.format('robot %d: removed %d blocks', robot, #segs))
else
  usage()
end
