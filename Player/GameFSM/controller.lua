-- The game state this robot follows: RoboCup GameController packets (UDP) when there are any,
-- else playing after a start delay; the robot's button toggles penalized.
--
--   local gc = require('GameFSM.controller').new(cfg)    -- cfg: Config behavior.lua
--   gc:update(t, button_pressed)  -> state name ('initial' ... 'finished'), penalized (bool)
--   gc.packets, gc.bad_packets (malformed, truncated, foreign: ignored), gc.score, gc.team_colour
local packet = require('GameFSM.packet')
local udp = require('GameFSM.udp')

local M = {}

local Controller = {}
Controller.__index = Controller

-- opts.port overrides the config's port (tests); opts.socket: an already open receiver
function M.new(cfg, opts)
  opts = opts or {}
  local port = opts.port or cfg.gamecontroller.port
  local sock, err = opts.socket, nil
  if sock == nil then sock, err = udp.listen(port) end
  if sock == false then sock = nil end -- no network (tests feed packets through receive())
  local c = setmetatable({
    cfg = cfg, sock = sock, socket_error = err, team = cfg.team_number, player = cfg.player_number,
    state = packet.STATE.initial, gc_penalized = false, manual_penalized = false,
    packets = 0, bad_packets = 0, foreign_packets = 0, gc_seen = false, t_start = nil,
    score = { 0, 0 }, team_colour = 0, kickoff_team = 0, last_penalty = 0, button_prev = false,
    last_packet_number = nil,
  }, Controller)
  return c
end

-- Continues a predecessor's game state (Player/Behavior/behavior.lua: a restarted process): the
-- state it followed, and a manual penalty it held (a GameController's packets decide again at once).
function Controller:resume(state, penalized)
  self.state = packet.STATE[state] or self.state
  self.resumed = true
  if penalized then self.manual_penalized = true end
end

-- Takes one datagram; true if it was a valid packet for this robot's team.
function Controller:receive(data)
  local p = packet.parse(data)
  if not p then self.bad_packets = self.bad_packets + 1 return false end
  local mine = packet.for_robot(p, self.team, self.player)
  if not mine then
    self.bad_packets = self.bad_packets + 1
    self.foreign_packets = self.foreign_packets + 1
    return false
  end
  self.packets = self.packets + 1
  self.gc_seen = true
  self.state = mine.state
  if mine.penalty ~= self.last_penalty then self.manual_penalized = false end
  self.last_penalty = mine.penalty
  self.gc_penalized = mine.penalized
  self.score = mine.score
  self.team_colour = mine.team_colour
  self.kickoff_team = mine.kickoff_team
  self.last_packet_number = p.packet_number
  return true
end

-- One step at robot time t; returns the state's name and whether the robot is penalized.
function Controller:update(t, button)
  if not self.t_start or t < (self.t_last or t) then self.t_start = t end -- first call, or the clock restarted
  self.t_last = t
  if self.sock then
    for _ = 1, 64 do -- bounded: a flood cannot stall the behavior
      local data = self.sock:receive()
      if not data then break end
      self:receive(data)
    end
  end
  if not self.gc_seen and t - self.t_start >= self.cfg.gamecontroller.start_delay then
    self.state = packet.STATE.playing
  end
  local pressed = button and true or false
  if pressed and not self.button_prev then self.manual_penalized = not self.manual_penalized end
  self.button_prev = pressed
  return packet.STATES[self.state], self:penalized()
end

function Controller:penalized()
  return self.gc_penalized ~= self.manual_penalized
end

function Controller:close()
  if self.sock then self.sock:close() self.sock = nil end
end

return M
