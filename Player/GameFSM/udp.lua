-- Non-blocking UDP through the FFI: a receiver bound to a port on the network interface the config
-- names (SO_BINDTODEVICE: datagrams from any other network never reach it; several robots on one
-- machine can bind the same port: SO_REUSEADDR, so each gets the broadcasts) and a sender. A receiver
-- reads into one fixed 4096-byte buffer and the kernel bounds its queue (SO_RCVBUF): a flood costs
-- dropped datagrams, never memory.
local ffi = require('ffi')

ffi.cdef [[
struct hrp_sockaddr_in { uint16_t family; uint16_t port; uint32_t addr; uint8_t zero[8]; };
int socket(int domain, int type, int protocol);
int bind(int fd, const struct hrp_sockaddr_in *addr, uint32_t len);
int setsockopt(int fd, int level, int optname, const void *optval, uint32_t optlen);
int getsockopt(int fd, int level, int optname, void *optval, uint32_t *optlen);
long recvfrom(int fd, void *buf, size_t len, int flags, struct hrp_sockaddr_in *src, uint32_t *srclen);
long sendto(int fd, const void *buf, size_t len, int flags, const struct hrp_sockaddr_in *dst,
           uint32_t dstlen);
int close(int fd);
uint16_t htons(uint16_t v);
uint32_t inet_addr(const char *cp);
char *strerror(int errnum);
]]
local C = ffi.C

local AF_INET, SOCK_DGRAM, SOCK_NONBLOCK = 2, 2, 2048
local SOL_SOCKET, SO_REUSEADDR, SO_BROADCAST, SO_RCVBUF, SO_BINDTODEVICE = 1, 2, 6, 8, 25
local RCVBUF = 65536 -- bytes queued at most (the kernel doubles it for its bookkeeping)
local MSG_DONTWAIT = 64

local M = {}

local one = ffi.new('int[1]', 1)
local buf_size = 4096
local buf = ffi.new('uint8_t[?]', buf_size)
local src = ffi.new('struct hrp_sockaddr_in')
local srclen = ffi.new('uint32_t[1]')

local function errstr() return ffi.string(C.strerror(ffi.errno())) end

local Socket = {}
Socket.__index = Socket

-- A receiver on `port` of the network interface `interface` ('lo', 'wlan0'; '' or nil: every
-- interface); nil and a message on failure.
function M.listen(port, interface)
  local fd = C.socket(AF_INET, SOCK_DGRAM + SOCK_NONBLOCK, 0)
  if fd < 0 then return nil, 'socket: ' .. errstr() end
  C.setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, one, 4)
  C.setsockopt(fd, SOL_SOCKET, SO_BROADCAST, one, 4)
  C.setsockopt(fd, SOL_SOCKET, SO_RCVBUF, ffi.new('int[1]', RCVBUF), 4)
  if interface and interface ~= '' then
    if C.setsockopt(fd, SOL_SOCKET, SO_BINDTODEVICE, interface, #interface) < 0 then
      local e = errstr()
      C.close(fd)
      return nil, string.format("UDP port %d: interface '%s': %s", port, interface, e)
    end
  end
  local addr = ffi.new('struct hrp_sockaddr_in')
  addr.family = AF_INET
  addr.port = C.htons(port)
  addr.addr = 0
  if C.bind(fd, addr, ffi.sizeof(addr)) < 0 then
    local e = errstr()
    C.close(fd)
    return nil, string.format('bind UDP port %d: %s', port, e)
  end
  return setmetatable({ fd = fd, port = port, interface = interface }, Socket)
end

-- A sender (for tests and tools); from_host: the local address to send from (tests: 127.0.0.2).
function M.sender(from_host)
  local fd = C.socket(AF_INET, SOCK_DGRAM, 0)
  if fd < 0 then return nil, 'socket: ' .. errstr() end
  C.setsockopt(fd, SOL_SOCKET, SO_BROADCAST, one, 4)
  if from_host then
    local addr = ffi.new('struct hrp_sockaddr_in')
    addr.family, addr.port, addr.addr = AF_INET, 0, C.inet_addr(from_host)
    if C.bind(fd, addr, ffi.sizeof(addr)) < 0 then
      local e = errstr()
      C.close(fd)
      return nil, string.format('bind to %s: %s', from_host, e)
    end
  end
  return setmetatable({ fd = fd }, Socket)
end

-- A set of allowed sender addresses from a config list ({} or nil: every sender); check(host) says
-- whether a datagram from host is taken.
function M.allow(list, where)
  local set, any = {}, true
  for i, h in ipairs(list or {}) do
    if type(h) ~= 'string' or not h:match('^%d+%.%d+%.%d+%.%d+$') then
      error(string.format('%s: element %d must be an IPv4 address like "10.0.0.1", not %s', where, i,
        tostring(h)), 2)
    end
    set[h], any = true, false
  end
  return function(host) return any or set[host] == true end
end

local src_bytes = ffi.cast('uint8_t *', src)

-- Next pending datagram as a string and its sender's address (dotted quad) and port, or nil when
-- none is waiting. A datagram longer than the buffer (4096 bytes) arrives cut to it. Each one read
-- goes to self.tap(data, host, port) when set (Lib/netlog.lua: the recorder's copy).
function Socket:receive()
  srclen[0] = ffi.sizeof(src)
  local n = C.recvfrom(self.fd, buf, buf_size, MSG_DONTWAIT, src, srclen)
  if n < 0 then return nil end
  local a = src_bytes + 4 -- the address, in network order
  local data = ffi.string(buf, n)
  local host, port = string.format('%d.%d.%d.%d', a[0], a[1], a[2], a[3]), src_bytes[2] * 256 + src_bytes[3]
  if self.tap then self.tap(data, host, port) end
  return data, host, port
end

-- Sends `data` to host:port (host as dotted quad); true or nil and a message.
function Socket:send(data, host, port)
  local dst = ffi.new('struct hrp_sockaddr_in')
  dst.family = AF_INET
  dst.port = C.htons(port)
  dst.addr = C.inet_addr(host)
  local n = C.sendto(self.fd, data, #data, 0, dst, ffi.sizeof(dst))
  if n < 0 then return nil, 'sendto: ' .. errstr() end
  return true
end

-- The interface the receiver is bound to ('' = every interface), as the kernel has it.
function Socket:device()
  local name, len = ffi.new('char[32]'), ffi.new('uint32_t[1]', 32)
  if C.getsockopt(self.fd, SOL_SOCKET, SO_BINDTODEVICE, name, len) < 0 then return nil, errstr() end
  return ffi.string(name)
end

function Socket:close()
  if self.fd >= 0 then C.close(self.fd) self.fd = -1 end
end

return M
