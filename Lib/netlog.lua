-- netlog: every UDP datagram a robot process reads (GameController packets, team messages) copied raw
-- into the net.packets ring (Config/shm.schema), from which the recorder writes them to their own
-- channels (/gamecontroller, /team.message): a log keeps what arrived, so a game with a
-- GameController can be looked at, and replayed, packet by packet. One writer per robot (the behavior).
--
--   local log = require('netlog').open()
--   sock.tap = log:tap(netlog.GAMECONTROLLER)   -- Player/GameFSM/udp.lua calls it per datagram read
--   log.t = t                                    -- the robot time stamped on what follows
local ffi = require('ffi')
local shm = require('shm')

local M = { GAMECONTROLLER = 1, TEAM = 2 }

local Log = {}
Log.__index = Log

-- The ring of robot opts.robot (default ROBOT_ID); nil and a message when the block cannot be opened.
function M.open(opts)
  local b, err = shm.open('net.packets', { robot = opts and opts.robot, try = true })
  if not b then return nil, err end
  local slots = b:count('source')
  return setmetatable({ b = b, slots = slots, slot_bytes = math.floor(b:count('data') / slots), t = 0 }, Log)
end

local function address(host)
  local a, b, c, d = (host or ''):match('^(%d+)%.(%d+)%.(%d+)%.(%d+)$')
  if not a then return 0 end
  return ((tonumber(a) * 256 + tonumber(b)) * 256 + tonumber(c)) * 256 + tonumber(d)
end

-- Appends one datagram (a string) from host:port, read at robot time self.t.
function Log:put(source, data, host, port)
  local b = self.b
  local k = b.written[0]
  local slot = k % self.slots
  local n = math.min(#data, self.slot_bytes)
  b:begin_write()
  b.source[slot], b.length[slot], b.time[slot] = source, n, self.t
  b.host[slot], b.port[slot] = address(host), port or 0
  ffi.copy(b.data + slot * self.slot_bytes, data, n)
  b.written[0] = k + 1
  b:end_write()
end

-- A function(data, host, port) that appends datagrams of `source` (a socket's tap).
function Log:tap(source)
  return function(data, host, port) self:put(source, data, host, port) end
end

return M
