-- Child processes for the process manager (Run/main.lua): spawn, reap, signal, through the FFI.
--
--   local proc = require('Run.proc')
--   proc.block_signals()                    -- SIGINT, SIGTERM, SIGCHLD only through proc.wait_signal
--   local pid = proc.spawn({ 'luajit', 'Player/Motion/main.lua' })
--   local sig = proc.wait_signal(1.0)       -- 'INT', 'TERM', 'CHLD' or nil after the timeout
--   for pid, how in proc.reap() do ... end  -- exited children: how = 'exit 1' / 'signal 11'
--
-- Children run in their own process group (Ctrl-C reaches only the manager, which stops them in
-- order) and get SIGTERM if the manager dies (PR_SET_PDEATHSIG), so none is left behind.
local ffi = require('ffi')

ffi.cdef [[
typedef int pid_t;
typedef struct { unsigned long val[16]; } hrp_sigset_t;
typedef struct { int signo; int errno_; int code; int pad[29]; } hrp_siginfo_t;
struct timespec { long tv_sec; long tv_nsec; };
pid_t fork(void);
int execvp(const char *file, char *const argv[]);
void _exit(int status);
pid_t waitpid(pid_t pid, int *status, int options);
int kill(pid_t pid, int sig);
int setpgid(pid_t pid, pid_t pgid);
int prctl(int option, unsigned long arg2, unsigned long arg3, unsigned long arg4, unsigned long arg5);
int sigemptyset(hrp_sigset_t *set);
int sigaddset(hrp_sigset_t *set, int signum);
int sigprocmask(int how, const hrp_sigset_t *set, hrp_sigset_t *oldset);
int sigtimedwait(const hrp_sigset_t *set, hrp_siginfo_t *info, const struct timespec *timeout);
pid_t getpid(void);
char *strerror(int errnum);
]]
local C = ffi.C

local M = {}

local SIGINT, SIGKILL, SIGTERM, SIGCHLD = 2, 9, 15, 17
local SIG_BLOCK, SIG_SETMASK = 0, 2
local WNOHANG = 1
local PR_SET_PDEATHSIG = 1
M.SIGINT, M.SIGKILL, M.SIGTERM = SIGINT, SIGKILL, SIGTERM

local handled = ffi.new('hrp_sigset_t')
C.sigemptyset(handled)
for _, s in ipairs({ SIGINT, SIGTERM, SIGCHLD }) do C.sigaddset(handled, s) end
local empty = ffi.new('hrp_sigset_t')
C.sigemptyset(empty)
local info = ffi.new('hrp_siginfo_t')
local ts = ffi.new('struct timespec')
local status = ffi.new('int[1]')

local NAMES = { [SIGINT] = 'INT', [SIGTERM] = 'TERM', [SIGCHLD] = 'CHLD' }

-- Blocks SIGINT, SIGTERM and SIGCHLD so that they are only taken by wait_signal.
function M.block_signals()
  C.sigprocmask(SIG_BLOCK, handled, nil)
end

-- Waits up to `timeout` seconds for one of the handled signals; returns its name or nil.
function M.wait_signal(timeout)
  timeout = math.max(0, timeout)
  ts.tv_sec = math.floor(timeout)
  ts.tv_nsec = math.floor((timeout - math.floor(timeout)) * 1e9)
  local s = C.sigtimedwait(handled, info, ts)
  if s < 0 then return nil end
  return NAMES[s] or tostring(s)
end

-- Starts argv (a table of strings, argv[1] searched in PATH) as a child in its own process
-- group; returns its pid, or nil and a message.
function M.spawn(argv)
  local n = #argv
  local cargv = ffi.new('char *[?]', n + 1)
  local keep = {}
  for i = 1, n do
    local s = ffi.new('char[?]', #argv[i] + 1)
    ffi.copy(s, argv[i])
    keep[i] = s
    cargv[i - 1] = s
  end
  cargv[n] = nil
  local pid = C.fork()
  if pid < 0 then return nil, 'fork failed: ' .. ffi.string(C.strerror(ffi.errno())) end
  if pid == 0 then
    -- child: only async-signal-safe calls until exec
    C.setpgid(0, 0)
    C.prctl(PR_SET_PDEATHSIG, SIGTERM, 0, 0, 0)
    C.sigprocmask(SIG_SETMASK, empty, nil)
    C.execvp(cargv[0], cargv)
    C._exit(127)
  end
  C.setpgid(pid, pid) -- also from the parent, so the group exists before we ever signal it
  M._last_argv = keep -- anchors the strings past the fork (the GC must not free them earlier)
  return pid
end

-- Describes a wait status: 'exit N' or 'signal N'.
local function describe(st)
  local sig = bit.band(st, 0x7f)
  if sig == 0 then return 'exit ' .. bit.band(bit.rshift(st, 8), 0xff), false end
  return 'signal ' .. sig, true
end

-- Iterator over children that have ended: pid, description ('exit N' / 'signal N').
function M.reap()
  return function()
    local pid = C.waitpid(-1, status, WNOHANG)
    if pid <= 0 then return nil end
    return pid, describe(status[0])
  end
end

-- Sends signal `sig` to the child's process group (and the child).
function M.signal(pid, sig)
  C.kill(-pid, sig)
  C.kill(pid, sig)
end

-- True while process `pid` exists.
function M.alive(pid)
  return C.kill(pid, 0) == 0
end

M.getpid = function() return C.getpid() end

return M
