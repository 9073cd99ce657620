-- Benchmark: one-way latency of a Lua write seen by a C reader in another process, through a
-- shm block and, in the same run, through a pipe. Prints p50/p99/max for both and the ratio.
--   luajit Tools/bench/shm_latency.lua [N]      (N updates, default 100000)
local ffi = require('ffi')
local shm = require('shm')
local native = require('native')

ffi.cdef [[
int open(const char *path, int flags, ...);
long write(int fd, const void *buf, size_t n);
long read(int fd, void *buf, size_t n);
int close(int fd);
int mkfifo(const char *path, unsigned mode);
int unlink(const char *path);
int sched_yield(void);
struct hrp_sched_param { int sched_priority; };
int sched_setscheduler(int pid, int policy, const struct hrp_sched_param *param);
int sched_setaffinity(int pid, size_t size, const uint64_t *mask);
]]

local N = tonumber(arg and arg[1]) or 100000
local C = shm.C
local dir = os.tmpname()
os.remove(dir)
local data_fifo, ack_fifo = dir .. '.data', dir .. '.ack'
assert(ffi.C.mkfifo(data_fifo, 384) == 0 and ffi.C.mkfifo(ack_fifo, 384) == 0, 'mkfifo failed')

-- real-time priority on core 0 (the reader takes core 1), as a DCM and motion process would run;
-- falls back to normal priority without permission
local mask = ffi.new('uint64_t[16]')
mask[0] = 1
local pinned = ffi.C.sched_setaffinity(0, ffi.sizeof(mask), mask) == 0
local prio = ffi.new('struct hrp_sched_param', { 10 })
local rt = ffi.C.sched_setscheduler(0, 1, prio) == 0   -- 1 = SCHED_FIFO
print(string.format('writer: %s, %s', pinned and 'pinned to cpu 0' or 'not pinned',
  rt and 'SCHED_FIFO' or 'normal priority'))

local bench = shm.open('bench')
bench.ack[0] = 0
local reader = io.popen(string.format('%s/build/bin/shm_latency_reader %d %s %s',
  native.root(), N, data_fifo, ack_fifo), 'r')

-- wait until the reader is attached and spinning
local ack = ffi.cast('volatile uint32_t *', bench.ack)
-- spin, yielding now and then so a loaded machine still makes progress
local function await(v)
  local spins = 0
  while ack[0] ~= v do
    spins = spins + 1
    if spins % 2000 == 0 then ffi.C.sched_yield() end
  end
end
await(0xffffffff)

for k = 1, N do
  bench:begin_write()
  bench.t_send[0] = C.shm_now()
  bench.k[0] = k
  bench:end_write()
  await(k)
end

local O_RDONLY, O_WRONLY = 0, 1
local wfd = ffi.C.open(data_fifo, O_WRONLY)
local afd = ffi.C.open(ack_fifo, O_RDONLY)
local t = ffi.new('double[1]')
local c = ffi.new('char[1]')
for _ = 1, N do
  t[0] = C.shm_now()
  ffi.C.write(wfd, t, 8)
  ffi.C.read(afd, c, 1)
end
ffi.C.close(wfd)
ffi.C.close(afd)
io.write(reader:read('*a'))
reader:close()
ffi.C.unlink(data_fifo)
ffi.C.unlink(ack_fifo)
shm.unlink('bench')
