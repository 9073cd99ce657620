-- Shared-memory blocks from Lua: typed arrays over the segment, no per-call copying.
--
--   local shm = require('shm')
--   local sensor = shm.open('dcm.sensor')        -- this robot's block (ROBOT_ID, default 1)
--   sensor.position[0]                           -- typed pointer (0-based), straight into shm
--   sensor:get('position')  --> Lua table (1-based) or a number for one-element fields
--   sensor:set('gyro', {0, 0, 0}); sensor:set('time', 1.5)
--   sensor:write(function(b) b.time[0] = t; b.tick[0] = n end)   -- seen whole by readers
--   sensor:read(function(b) return b.time[0], b.tick[0] end)      -- retried until consistent
local ffi = require('ffi')
local native = require('native')

ffi.cdef [[
typedef struct shm_schema shm_schema;
typedef struct shm_block shm_block;
typedef struct shm_field { char name[48]; uint32_t type; uint32_t count; uint64_t offset; } shm_field;
int shm_schema_load(const char *path, shm_schema **out, char *err, size_t errlen);
void shm_schema_free(shm_schema *schema);
int shm_schema_nblocks(const shm_schema *schema);
const char *shm_schema_block_name(const shm_schema *schema, int i);
long shm_schema_const(const shm_schema *schema, const char *name);
int shm_robot_id(void);
int shm_block_open(const shm_schema *schema, const char *block, int robot_id, int flags,
                   shm_block **out, char *err, size_t errlen);
void shm_block_close(shm_block *b);
int shm_block_unlink(const char *block, int robot_id);
int shm_block_replaced(const shm_block *b);
const shm_field *shm_block_field(const shm_block *b, int i);
int shm_block_nfields(const shm_block *b);
void *shm_field_ptr(shm_block *b, const char *field, int *type, int *count);
void shm_write_begin(shm_block *b);
void shm_write_end(shm_block *b);
uint32_t shm_read_begin(const shm_block *b);
int shm_read_begin_checked(const shm_block *b, uint32_t *seq, char *err, size_t errlen);
int shm_read_retry(const shm_block *b, uint32_t seq);
uint32_t shm_wait_write(shm_block *b, uint32_t last, double timeout_s);
int shm_futex_wait(volatile uint32_t *addr, uint32_t val, double timeout_s);
int shm_futex_wake(volatile uint32_t *addr);
int shm_cas_i32(volatile int32_t *addr, int32_t expected, int32_t desired);
uint32_t shm_fetch_add_u32(volatile uint32_t *addr, uint32_t delta);
double shm_now(void);
int shm_pid_alive(int pid);
int shm_pid_stopped(int pid);
]]

local C = native.load('shm')

local M = { C = C }

local CTYPES = {
  [1] = ffi.typeof('double *'), [2] = ffi.typeof('float *'), [3] = ffi.typeof('int32_t *'),
  [4] = ffi.typeof('uint32_t *'), [5] = ffi.typeof('int64_t *'), [6] = ffi.typeof('uint64_t *'),
  [7] = ffi.typeof('uint8_t *'), [8] = ffi.typeof('int16_t *'), [9] = ffi.typeof('uint16_t *'),
}
local TYPE_NAMES = { 'f64', 'f32', 'i32', 'u32', 'i64', 'u64', 'u8', 'i16', 'u16' }
M.TYPE_NAMES = TYPE_NAMES

local OPEN_CREATE, OPEN_NOSCHEMA = 1, 2

local errbuf = ffi.new('char[512]')
local handle_out = ffi.new('shm_block *[1]')
local schema_out = ffi.new('shm_schema *[1]')

local schema -- loaded once per process
local function get_schema()
  if not schema then
    local rc = C.shm_schema_load(nil, schema_out, errbuf, 512)
    if rc < 0 then error(ffi.string(errbuf), 3) end
    schema = ffi.gc(schema_out[0], C.shm_schema_free)
  end
  return schema
end

-- The robot this process serves: $ROBOT_ID, default 1.
function M.robot_id() return C.shm_robot_id() end

-- Names of every block in the schema.
function M.block_names()
  local s = get_schema()
  local names = {}
  for i = 0, C.shm_schema_nblocks(s) - 1 do names[#names + 1] = ffi.string(C.shm_schema_block_name(s, i)) end
  return names
end

-- A schema constant such as 'njoint'.
function M.const(name)
  local v = tonumber(C.shm_schema_const(get_schema(), name))
  if v < 0 then error("shm schema has no constant '" .. name .. "'", 2) end
  return v
end

local Block = {}
Block.__index = Block

local cache = {}

-- Maps segment `name` of `robot` into block table b (new or, for reopen, in use): handle and
-- field pointers. nil, err on failure.
local function bind(b, name, robot, opts)
  local flags = opts.raw and OPEN_NOSCHEMA or (opts.attach and 0 or OPEN_CREATE)
  local rc = C.shm_block_open(opts.raw and nil or get_schema(), name, robot, flags, handle_out, errbuf, 512)
  if rc < 0 then return nil, ffi.string(errbuf) end
  local handle = ffi.gc(handle_out[0], C.shm_block_close)
  local fields, order = {}, {}
  for i = 0, C.shm_block_nfields(handle) - 1 do
    local f = C.shm_block_field(handle, i)
    local fname = ffi.string(f.name)
    if Block[fname] then
      return nil, "shm block '" .. name .. "': field name '" .. fname .. "' clashes with a method"
    end
    local ptr = ffi.cast(CTYPES[f.type], C.shm_field_ptr(handle, fname, nil, nil))
    fields[fname] = { ptr = ptr, count = f.count, type = TYPE_NAMES[f.type] }
    order[#order + 1] = fname
  end
  for _, fname in ipairs(rawget(b, '_order') or {}) do rawset(b, fname, nil) end
  for fname, f in pairs(fields) do rawset(b, fname, f.ptr) end
  rawset(b, '_handle', handle)
  rawset(b, '_name', name)
  rawset(b, '_robot', robot)
  rawset(b, '_opts', opts)
  rawset(b, '_fields', fields)
  rawset(b, '_order', order)
  return b
end

-- Opens (creating if needed) block `name` of robot opts.robot (default ROBOT_ID).
-- opts.attach: only attach to an existing segment; opts.raw: take the layout from the segment
-- itself (tools), not from the schema. Errors name the block and what is wrong.
function M.open(name, opts)
  opts = opts or {}
  local robot = opts.robot or M.robot_id()
  local key = robot .. '/' .. name .. (opts.raw and '/raw' or '')
  if cache[key] then return cache[key] end
  local b, err = bind(setmetatable({}, Block), name, robot, opts)
  if not b then
    if opts.try then return nil, err end
    error(err, 2)
  end
  cache[key] = b
  return b
end

-- The blocks this process has open (shm.open's, of any robot) whose segment was replaced under it
-- (Block:replaced): a list sorted by name, empty if none.
function M.replaced()
  local list = {}
  for _, b in pairs(cache) do
    if b:replaced() then list[#list + 1] = b end
  end
  table.sort(list, function(a, b) return a._name < b._name end)
  return list
end

-- A function returning block `name`, opened at its first call (modules that are loaded before
-- the DCM has created the blocks, e.g. in the REPL).
function M.lazy(name, opts)
  local b
  return function()
    b = b or M.open(name, opts)
    return b
  end
end

-- Removes a block's segment (existing mappings stay valid). True if it existed.
function M.unlink(name, robot)
  cache[(robot or M.robot_id()) .. '/' .. name] = nil
  return C.shm_block_unlink(name, robot or M.robot_id()) == 0
end

local function field(b, name)
  local f = b._fields[name]
  if not f then error("shm block '" .. b._name .. "' has no field '" .. tostring(name) .. "'", 3) end
  return f
end

-- Value of a field: a number for one element, else a new table (1-based).
function Block:get(name)
  local f = field(self, name)
  if f.count == 1 then return tonumber(f.ptr[0]) end
  local t = {}
  for i = 0, f.count - 1 do t[i + 1] = tonumber(f.ptr[i]) end
  return t
end

-- Sets a field from a number (one element, or all elements) or a table (1-based).
function Block:set(name, value)
  local f = field(self, name)
  if type(value) == 'table' then
    if #value > f.count then
      error(string.format("shm block '%s' field '%s' holds %d values, got %d", self._name, name, f.count, #value), 2)
    end
    for i = 1, #value do f.ptr[i - 1] = value[i] end
  elseif type(value) == 'number' then
    for i = 0, f.count - 1 do f.ptr[i] = value end
  else
    error("shm set: value must be a number or a table, got " .. type(value), 2)
  end
end

function Block:count(name) return field(self, name).count end
function Block:type(name) return field(self, name).type end
function Block:fields() return self._order end
function Block:name() return self._name end

-- Runs fn(self) inside the block's sequence lock: readers see all of its writes or none.
function Block:write(fn)
  C.shm_write_begin(self._handle)
  local ok, err = pcall(fn, self)
  C.shm_write_end(self._handle)
  if not ok then error(err, 2) end
end

function Block:begin_write() C.shm_write_begin(self._handle) end
function Block:end_write() C.shm_write_end(self._handle) end

-- Runs fn(self) until it ran without a concurrent write; returns fn's results. A block whose writer
-- died (or had its pid reused) or is stopped mid-update is an error naming it and the pid (never a
-- reader spinning for ever).
local seq_out = ffi.new('uint32_t[1]')
function Block:read(fn)
  while true do
    if C.shm_read_begin_checked(self._handle, seq_out, errbuf, 512) < 0 then error('shm ' .. ffi.string(errbuf), 2) end
    local seq = seq_out[0]
    local a, b, c, d = fn(self)
    if C.shm_read_retry(self._handle, seq) == 0 then return a, b, c, d end
  end
end

-- Waits until the block's completed locked writes differ from `last`; returns the count.
function Block:wait_write(last, timeout)
  return C.shm_wait_write(self._handle, last or 0, timeout or 1.0)
end

-- True when the block's name now leads to another segment or none (removed, or recreated with another
-- layout while this process kept its mapping): what this process reads, nobody else writes any more.
function Block:replaced()
  return C.shm_block_replaced(self._handle) == 1
end

-- Maps the block again, in place (this table; every field pointer renewed: a pointer taken from it
-- before stays on the old segment), onto what its name holds now (a segment created if none).
-- For a process that reads fields through the table (a supervisor); true, or nil, err.
function Block:reopen()
  local ok, err = bind(self, self._name, self._robot, self._opts)
  return ok and true, err
end

-- All fields as a table (for dumps).
function Block:dump()
  local t = {}
  for _, name in ipairs(self._order) do t[name] = self:get(name) end
  return t
end

return M
