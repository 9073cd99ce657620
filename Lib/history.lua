-- The recent past of any shm field, from the ring the recorder keeps (Run/recorder/history.c: the
-- shared-memory object /hrp-history.<ROBOT_ID>, history_s seconds of every small block):
--
--   local history = require('history')
--   local t, v = history('dcm.sensor.gyro', 2.0)   -- times (s, robot clock) and values over the last 2 s,
--                                                   -- oldest first; v[i] a number, or a table for arrays
--   history('dcm.sensor.gyro', 2.0, 3)             -- one element (1-based): numbers
--
-- Errors (raised, naming the field): no recorder running for the robot, no such block or field.
local ffi = require('ffi')
local shm = require('shm')

local HEADER, ENTRY, FIELD = 64, 128, 64
local CTYPES = { 'double', 'float', 'int32_t', 'uint32_t', 'int64_t', 'uint64_t', 'uint8_t', 'int16_t', 'uint16_t' }
local u8p = ffi.typeof('const uint8_t *')

local function u32(p, at) return tonumber(ffi.cast('const uint32_t *', p + at)[0]) end
local function u64(p, at) return tonumber(ffi.cast('const uint64_t *', p + at)[0]) end
local function f64(p, at) return tonumber(ffi.cast('const double *', p + at)[0]) end

local function read_ring(robot)
  local path = string.format('/dev/shm/hrp-history.%d', robot)
  local f = io.open(path, 'rb')
  if not f then
    error(string.format('history: no ring %s: is the recorder running (./run_main --record)?', path), 3)
  end
  local bytes = f:read('*a')
  f:close()
  if #bytes < HEADER or bytes:sub(1, 8) ~= 'HRPHIST\1' then
    error('history: ' .. path .. ' is not a history ring', 3)
  end
  return bytes
end

-- The block entry and field of 'block.name.field' (block names contain dots: the longest match wins).
local function find(p, path)
  local nblocks = u32(p, 12)
  for i = 0, nblocks - 1 do
    local e = HEADER + i * ENTRY
    local name = ffi.string(p + e)
    if path:sub(1, #name + 1) == name .. '.' then
      local fname = path:sub(#name + 2)
      local fields, nfields = u64(p, e + 72), u32(p, e + 80)
      for k = 0, nfields - 1 do
        local fe = fields + k * FIELD
        if ffi.string(p + fe) == fname then
          return e, { type = u32(p, fe + 48), count = u32(p, fe + 52), offset = u64(p, fe + 56) }
        end
      end
      error(string.format("history: block '%s' has no field '%s'", name, fname), 3)
    end
  end
  error(string.format("history: no block of '%s' in the ring (a block larger than 64 kB is not kept)", path), 3)
end

local function history(path, seconds, element)
  if type(path) ~= 'string' or type(seconds) ~= 'number' or seconds < 0 then
    error("history(path, seconds): e.g. history('dcm.sensor.gyro', 2.0)", 2)
  end
  local bytes = read_ring(shm.robot_id())
  local p = ffi.cast(u8p, bytes)
  local e, fld = find(p, path)
  if element and (element < 1 or element > fld.count) then
    error(string.format("history: '%s' has %d elements, asked for %d", path, fld.count, element), 2)
  end
  local slots, slot_size, ring, count = u32(p, e + 48), u32(p, e + 52), u64(p, e + 64), u64(p, e + 88)
  local ctype = ffi.typeof(CTYPES[fld.type] .. ' *')
  local times, values = {}, {}
  local newest
  for k = count - 1, math.max(0, count - slots), -1 do
    local s = ring + (k % slots) * slot_size
    if u64(p, s + 8) ~= k + 1 then break end          -- being rewritten: older samples are gone
    local t = f64(p, s)
    newest = newest or t
    if t < newest - seconds then break end
    local v = ffi.cast(ctype, p + s + 16 + fld.offset)
    local value
    if element then value = tonumber(v[element - 1])
    elseif fld.count == 1 then value = tonumber(v[0])
    else
      value = {}
      for j = 0, fld.count - 1 do value[j + 1] = tonumber(v[j]) end
    end
    times[#times + 1], values[#values + 1] = t, value
  end
  -- oldest first
  local n = #times
  for i = 1, math.floor(n / 2) do
    times[i], times[n + 1 - i] = times[n + 1 - i], times[i]
    values[i], values[n + 1 - i] = values[n + 1 - i], values[i]
  end
  return times, values
end

return history
