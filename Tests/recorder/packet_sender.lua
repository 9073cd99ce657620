-- The recorder's packet test (Tests/recorder/packets_test.sh): GameController packets and team messages
-- sent over loopback to receivers tapped as the behavior taps its own (Player/GameFSM/udp.lua ->
-- Lib/netlog.lua -> net.packets). A slow phase (one of each per 100 ms: the recorder takes every one),
-- then a burst of team messages read at once, more than the ring holds (the recorder must count what it
-- lost). Writes each datagram read as "<source> <hex>" to OUT for the checker.
--   luajit Tests/recorder/packet_sender.lua PORT OUT [SLOW] [BURST]
local ffi = require('ffi')
local udp = require('GameFSM.udp')
local packet = require('GameFSM.packet')
local message = require('Team.message')
local netlog = require('netlog')

ffi.cdef [[ int usleep(unsigned int usec); ]]

local port, out = tonumber(arg[1]), arg[2]
local slow, burst = tonumber(arg[3]) or 10, tonumber(arg[4]) or 40
local log = assert(netlog.open())
local gc_sock = assert(udp.listen(port, 'lo'))
local team_sock = assert(udp.listen(port + 1, 'lo'))
gc_sock.tap = log:tap(netlog.GAMECONTROLLER)
team_sock.tap = log:tap(netlog.TEAM)
local tx = assert(udp.sender('127.0.0.1'))
local f = assert(io.open(out, 'w'))

local function hex(s) return (s:gsub('.', function(c) return string.format('%02x', c:byte()) end)) end

-- reads what was sent on sock (loopback delivers at once; a short wait covers a busy machine)
local function drain(sock, source, want)
  local got = 0
  for _ = 1, 200 do
    local data = sock:receive()
    if data then
      got = got + 1
      f:write(source, ' ', hex(data), '\n')
      if got == want then return end
    else
      ffi.C.usleep(1000)
    end
  end
  error(string.format('only %d of %d datagrams arrived on port %d', got, want, sock.port))
end

local function team_message(k)
  return message.encode({ player_id = k % 4 + 1, team = 'red', pose = { k * 0.1, -k * 0.05, 0.3 },
    ball = { 1, 2, 0 }, ball_velocity = { 0, 0, 0 }, state = 'unpenalised', walk = { 0.1, 0, 0 }, stamp = { k, 0 } })
end

for i = 1, slow do
  log.t = i * 0.1
  assert(tx:send(packet.build({ packet_number = i % 256, state = i % 5, secs_remaining = 600 - i,
    teams = { { number = 7, score = i }, { number = 9 } } }), '127.0.0.1', port))
  assert(tx:send(team_message(i), '127.0.0.1', port + 1))
  drain(gc_sock, 'gamecontroller', 1)
  drain(team_sock, 'team', 1)
  ffi.C.usleep(100000)
end
log.t = (slow + 1) * 0.1
for k = 1, burst do assert(tx:send(team_message(100 + k), '127.0.0.1', port + 1)) end
drain(team_sock, 'team', burst)
f:close()
io.stdout:write(string.format('packet_sender: %d GameController packets, %d team messages\n', slow, slow + burst))
