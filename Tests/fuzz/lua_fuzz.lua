-- A mutational fuzzer for parsers written in Lua, run like a libFuzzer binary (Tests/fuzz_lib.sh):
--   luajit Tests/fuzz/lua_fuzz.lua TARGET [-max_total_time=S] [-max_len=N] [-seed=N]
--     [-artifact_prefix=P] [other libFuzzer flags, ignored] SEED_DIR|INPUT_FILE
-- TARGET is a module (e.g. Tests.game.gc_fuzz) returning
--   { seeds = function() return { bytes, ... } end,   valid inputs built from the real layout
--     dictionary = { 'RGme', ... },                    tokens worth planting (optional)
--     cover = { 'Player/GameFSM/' },                    sources whose lines guide the corpus
--     run = function(bytes) ... end }                   raises on any finding (an escaped error or
--                                                       a broken invariant)
-- Inputs that reach a new pair of consecutive lines in the `cover` sources join the corpus (and
-- the seed folder, as libFuzzer does). A finding is written to artifact_prefix .. 'crash-N' and
-- ends the run with exit status 1; an INPUT_FILE instead of a folder runs that input once.
local ffi = require('ffi')

local target_name = arg[1]
if not target_name then
  io.stderr:write('usage: luajit Tests/fuzz/lua_fuzz.lua TARGET [flags] SEED_DIR|INPUT\n')
  os.exit(2)
end
local opts, path = { max_total_time = 10, max_len = 4096, seed = os.time(), artifact_prefix = './' }, nil
for i = 2, #arg do
  local k, v = arg[i]:match('^%-([%w_]+)=(.*)$')
  if k then opts[k] = tonumber(v) or v else path = arg[i] end
end
if not path then io.stderr:write('lua_fuzz: a seed folder or an input file is needed\n') os.exit(2) end
local target = require(target_name)

local read = require('Tests.files').read

local function is_dir(p) return os.execute('test -d "' .. p .. '"') == 0 end

local function finding(data, err)
  local file = opts.artifact_prefix .. 'crash-' .. os.time()
  local f = io.open(file, 'wb')
  if f then f:write(data) f:close() end
  io.write('==ERROR: lua_fuzz: ', tostring(err), '\n')
  io.write('SUMMARY: lua_fuzz: a finding in ', target_name, '; input (', #data, ' bytes) written to ',
    file, '\n')
  os.exit(1)
end

local function execute(data)
  local ok, err = xpcall(target.run, debug.traceback, data)
  if not ok then finding(data, err) end
end

if not is_dir(path) then -- reproduce one input
  execute(read(path))
  print('lua_fuzz: ' .. path .. ': no finding')
  os.exit(0)
end

-- coverage: pairs of consecutive lines executed in the cover sources (the interpreter only: the
-- hooks do not see JIT-compiled code)
jit.off()
local seen, fresh, prev = {}, 0, 0
local cover_src = {}
local getinfo = debug.getinfo
local function hook(_, line)
  local src = getinfo(2, 'S').source
  local ok = cover_src[src]
  if ok == nil then
    ok = false
    for _, pat in ipairs(target.cover or {}) do if src:find(pat, 1, true) then ok = true end end
    cover_src[src] = ok
  end
  if not ok then return end
  local key = prev * 65536 + line
  if not seen[key] then seen[key], fresh = true, fresh + 1 end
  prev = line
end
local function run_covered(data)
  fresh, prev = 0, 0
  debug.sethook(hook, 'l')
  local ok, err = xpcall(target.run, debug.traceback, data)
  debug.sethook()
  if not ok then finding(data, err) end
  return fresh > 0
end

-- the corpus: the target's seeds, then the folder's files
math.randomseed(opts.seed)
local rnd = math.random
local corpus = {}
local nfile = 0
local function keep(data, write)
  corpus[#corpus + 1] = data
  if write then
    nfile = nfile + 1
    local f = io.open(string.format('%s/lua-%d-%d', path, opts.seed, nfile), 'wb')
    if f then f:write(data) f:close() end
  end
end
for i, s in ipairs(target.seeds()) do
  run_covered(s)
  keep(s, false)
  local f = io.open(string.format('%s/seed-%d', path, i), 'wb')
  if f then f:write(s) f:close() end
end
local p = io.popen('ls "' .. path .. '"')
for name in p:lines() do
  if not name:match('^seed%-') then
    local s = read(path .. '/' .. name):sub(1, opts.max_len)
    if run_covered(s) then keep(s, false) end
  end
end
p:close()

-- mutations on a byte buffer
local MAX = opts.max_len
local buf = ffi.new('uint8_t[?]', MAX + 1)
local tmp = ffi.new('uint8_t[?]', MAX + 1)
local BYTES = { 0, 1, 2, 3, 4, 5, 9, 10, 11, 12, 14, 16, 32, 64, 100, 127, 128, 200, 254, 255 }
local WORDS = { 0, 1, 2, 12, 255, 256, 688, 0x7fff, 0x8000, 0xfffe, 0xffff }
local dict = target.dictionary or {}

local function mutate(len)
  local m = rnd(12)
  if m == 1 and len > 0 then local i = rnd(0, len - 1) buf[i] = bit.bxor(buf[i], bit.lshift(1, rnd(0, 7)))
  elseif m == 2 and len > 0 then buf[rnd(0, len - 1)] = rnd(0, 255)
  elseif m == 3 and len > 0 then buf[rnd(0, len - 1)] = BYTES[rnd(#BYTES)]
  elseif m == 4 and len > 1 then
    local i, w = rnd(0, len - 2), WORDS[rnd(#WORDS)]
    buf[i], buf[i + 1] = w % 256, math.floor(w / 256)
  elseif m == 5 and len > 0 then -- delete a range
    local i = rnd(0, len - 1)
    local k = rnd(1, math.min(len - i, 64))
    ffi.copy(tmp, buf + i + k, len - i - k)
    ffi.copy(buf + i, tmp, len - i - k)
    len = len - k
  elseif m == 6 and len < MAX then -- insert random bytes
    local i = rnd(0, len)
    local k = rnd(1, math.min(MAX - len, 64))
    ffi.copy(tmp, buf + i, len - i)
    for j = 0, k - 1 do buf[i + j] = rnd(0, 255) end
    ffi.copy(buf + i + k, tmp, len - i)
    len = len + k
  elseif m == 7 and len > 0 then len = rnd(0, len - 1) -- truncate
  elseif m == 8 and len < MAX then -- append
    local k = rnd(1, math.min(MAX - len, 16))
    for j = 0, k - 1 do buf[len + j] = rnd(0, 255) end
    len = len + k
  elseif m == 9 then -- splice with another input: this one's head, that one's tail
    local o = corpus[rnd(#corpus)]
    local i = rnd(0, len)
    local j = rnd(0, #o)
    local k = math.min(#o - j, MAX - i)
    ffi.copy(buf + i, o:sub(j + 1, j + k), k)
    len = i + k
  elseif m == 10 and #dict > 0 then -- a token, at the start or anywhere
    local t = dict[rnd(#dict)]
    local i = rnd(2) == 1 and 0 or rnd(0, len)
    if i + #t <= MAX then ffi.copy(buf + i, t, #t) len = math.max(len, i + #t) end
  elseif m == 11 and len > 1 then -- copy a chunk within
    local a, b = rnd(0, len - 1), rnd(0, len - 1)
    local k = rnd(1, math.min(len - a, len - b))
    ffi.copy(tmp, buf + a, k)
    ffi.copy(buf + b, tmp, k)
  elseif m == 12 and len > 0 then -- a run of one byte
    local i = rnd(0, len - 1)
    local k = rnd(1, math.min(len - i, 32))
    ffi.fill(buf + i, k, rnd(2) == 1 and 0 or 255)
  end
  return len
end

-- wall time, as libFuzzer's max_total_time
local t0 = os.time()
local units, added = 0, 0
io.write('INFO: lua_fuzz ', target_name, ' -seed=', opts.seed, ', ', #corpus, ' inputs in the corpus\n')
while os.time() - t0 < opts.max_total_time do
  for _ = 1, 64 do
    local base = corpus[rnd(#corpus)]
    local len = math.min(#base, MAX)
    ffi.copy(buf, base, len)
    for _ = 1, bit.lshift(1, rnd(0, 3)) do len = mutate(len) end
    local data = ffi.string(buf, len)
    units = units + 1
    if run_covered(data) then keep(data, true) added = added + 1 end
  end
end
local edges = 0
for _ in pairs(seen) do edges = edges + 1 end
print(string.format('Done %d runs in %d second(s)', units, os.time() - t0))
print('stat::number_of_executed_units: ' .. units)
print('stat::new_units_added: ' .. added)
print('stat::line_pairs_covered: ' .. edges)
print('stat::corpus_size: ' .. #corpus)
