-- A test GameController for scenario scripts run by ./run_repl inside the sim's lockstep: sends
-- packets built with Player/GameFSM/packet.lua twice a second of robot time, reads the robot's
-- return packets, and waits for the robot's processes to join the lockstep.
--   local gc = require('Tests.game.gc_sim').new(port, return_port, team)
--   gc.packet = { state = ..., secondary_state = ..., ... }  (what to send; teams filled in)
--   gc.penalty = 34    the robot's penalty in what is sent (gc.player: its number, default 1)
--   gc:tick()          send when due (call before each wait())
--   gc:returns()       return packets received since the last call, parsed (gc.log: all of them)
local ffi = require('ffi')
local shm = require('shm')
local packet = require('GameFSM.packet')
local udp = require('GameFSM.udp')
local Body = require('Body')
local participants = require('Tests.scenario_lib').participants
ffi.cdef [[ int usleep(unsigned int usec); ]]

local M = {}
local GC = {}
GC.__index = GC

M.OTHER = 99 -- the opponents' team number

function M.new(port, return_port, team)
  local rx
  if return_port then rx = assert(udp.listen(return_port)) end
  return setmetatable({ port = port, tx = assert(udp.sender()), rx = rx, team = team, number = 0,
    next = -1, packet = { state = packet.STATE.initial }, log = {} }, GC)
end

function GC:send()
  self.number = (self.number + 1) % 256
  local p = {}
  for k, v in pairs(self.packet) do p[k] = v end
  p.packet_number = self.number
  local players = {}
  players[self.player or 1] = { penalty = self.penalty or 0 }
  p.teams = { { number = self.team, players = players }, { number = M.OTHER } }
  assert(self.tx:send(packet.build(p), '127.0.0.1', self.port))
end

function GC:tick()
  if Body.get_time() < self.next then return end
  self.next = Body.get_time() + 0.5
  self:send()
end

-- Changes what is sent and sends it at once.
function GC:set(p)
  self.packet = p
  self:send()
  self.next = Body.get_time() + 0.5
end

function GC:returns()
  local list = {}
  while self.rx do
    local data = self.rx:receive()
    if not data then break end
    local p = packet.parse_return(data) or { bad = data }
    list[#list + 1] = p
    self.log[#self.log + 1] = p
  end
  return list
end

-- Waits (wall clock, the robot's clock held) until n participants (the robot's processes and this
-- script) take part in the lockstep (of robot id `robot`, default this script's).
function M.joined(n, robot)
  local sync = shm.open('sync', robot and { robot = robot } or nil)
  local deadline = os.time() + 60
  while true do
    if participants(sync) >= n then return end
    assert(os.time() < deadline, 'the robot processes did not join the lockstep within 60 s')
    ffi.C.usleep(20000)
  end
end

return M
