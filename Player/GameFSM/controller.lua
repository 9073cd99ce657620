-- The game state this robot follows: RoboCup GameController packets (UDP) when there are any;
-- without a GameController, the configured start (Config/common/game.lua: wait in INITIAL for the
-- button, or play after a delay). The robot answers a GameController with return packets: alive
-- about once a second, and the chest button as a manual penalise / unpenalise request (the
-- GameController's packets decide; without one the button toggles a penalty itself).
--
--   local gc = require('GameFSM.controller').new(cfg)  -- cfg: team_number, player_number, gamecontroller
--   gc:update(t, button_pressed)  -> state name ('initial' ... 'finished'), penalized (bool)
--   gc:view()                     -> the game as the GameFSM reads it (set plays, kick-off, goalkeeper)
--   gc.packets, gc.bad_packets (malformed, truncated, foreign: ignored), gc.returns, gc.score,
--   gc.rejected (datagrams from a host not in gamecontroller.hosts: not even parsed)
-- The socket hears only gamecontroller.interface (Player/GameFSM/udp.lua).
local packet = require('GameFSM.packet')
local udp = require('GameFSM.udp')

local M = {}

local Controller = {}
Controller.__index = Controller

-- opts.port / opts.return_port override the config's ports (tests); opts.socket: an already open
-- receiver, or false for none (tests feed packets through receive() and read opts.sent).
function M.new(cfg, opts)
  opts = opts or {}
  local g = cfg.gamecontroller
  if g.start_without ~= 'initial' and g.start_without ~= 'playing' then
    error(string.format("game.lua: gamecontroller.start_without must be 'initial' or 'playing', not '%s'",
      tostring(g.start_without)), 2)
  end
  local sock, err = opts.socket, nil
  if sock == nil then sock, err = udp.listen(opts.port or g.port, g.interface) end
  if sock == false then sock = nil end
  return setmetatable({
    cfg = cfg, sock = sock, socket_error = err, team = cfg.team_number, player = cfg.player_number,
    return_port = opts.return_port or g.return_port, sent = opts.sent,
    state = packet.STATE.initial, gc_penalized = false, manual_penalized = false,
    allowed = udp.allow(g.hosts, 'game.lua gamecontroller.hosts'), rejected = 0,
    packets = 0, bad_packets = 0, foreign_packets = 0, returns = 0, gc_seen = false, gc_host = nil,
    t_start = nil, last_alive = -math.huge, button_prev = false, started = false,
    score = { 0, 0 }, team_colour = 0, kickoff_team = 0, first_half = 1, secondary_state = 0, secondary_team = 0,
    secondary_mode = 0, secondary_time = 0, secs_remaining = 0, goalkeeper = false, goalkeeper_player = 0,
    last_packet_number = nil,
  }, Controller)
end

-- Continues a predecessor's game state (Player/Behavior/behavior.lua: a restarted process): the
-- state it followed and a penalty it held (a GameController's packets decide again at once).
function Controller:resume(state, penalized)
  self.state = packet.STATE[state] or self.state
  self.started = self.state ~= packet.STATE.initial
  self.manual_penalized = penalized and true or false
end

-- Takes one datagram from `host`; true if it was a valid packet for this robot's team.
function Controller:receive(data, host)
  local p = packet.parse(data)
  if not p then self.bad_packets = self.bad_packets + 1 return false end
  local mine = packet.for_robot(p, self.team, self.player)
  if not mine then
    self.bad_packets = self.bad_packets + 1
    self.foreign_packets = self.foreign_packets + 1
    return false
  end
  self.packets = self.packets + 1
  self.gc_seen, self.gc_host = true, host or self.gc_host
  self.manual_penalized = false -- a GameController decides penalties from now on
  self.state, self.gc_penalized = mine.state, mine.penalized
  self.score, self.team_colour, self.kickoff_team = mine.score, mine.team_colour, mine.kickoff_team
  self.secondary_state, self.secondary_team = mine.secondary_state, mine.secondary_team
  self.secondary_mode, self.secondary_time = mine.secondary_mode, mine.secondary_time
  self.secs_remaining, self.goalkeeper = mine.secs_remaining, mine.goalkeeper
  self.first_half = mine.first_half or 1
  self.goalkeeper_player = mine.goalkeeper_player
  self.last_packet_number = p.packet_number
  return true
end

-- Sends a return packet to the GameController last heard (none heard: nothing to answer).
function Controller:answer(message)
  if not self.gc_host then return false end
  local data = packet.build_return(self.team, self.player, message)
  if self.sent then self.sent[#self.sent + 1] = data
  elseif self.sock then
    if not self.sock:send(data, self.gc_host, self.return_port) then return false end
  else return false end
  self.returns = self.returns + 1
  return true
end

-- One step at robot time t; returns the state's name and whether the robot is penalized.
function Controller:update(t, button)
  if not self.t_start or t < (self.t_last or t) then -- first call, or the clock restarted
    self.t_start, self.last_alive = t, -math.huge
  end
  self.t_last = t
  if self.sock then
    for _ = 1, 64 do -- bounded: a flood cannot stall the behavior
      local data, host = self.sock:receive()
      if not data then break end
      if self.allowed(host) then self:receive(data, host) else self.rejected = self.rejected + 1 end
    end
  end
  local g = self.cfg.gamecontroller
  if not self.gc_seen and not self.started and g.start_without == 'playing'
    and t - self.t_start >= g.start_delay then
    self.state, self.started = packet.STATE.playing, true
  end
  local pressed = button and true or false
  if pressed and not self.button_prev then self:press() end
  self.button_prev = pressed
  if self.gc_seen and t - self.last_alive >= g.alive_period then
    self.last_alive = t
    self:answer(packet.MSG.alive)
  end
  return packet.STATES[self.state], self:penalized()
end

-- The chest button: reported to a GameController (its packets decide); without one it starts a
-- robot waiting in INITIAL, and afterwards toggles a penalty (the button is the only referee).
function Controller:press()
  if self.gc_seen then
    self:answer(self.gc_penalized and packet.MSG.man_unpenalise or packet.MSG.man_penalise)
  elseif not self.started then
    self.state, self.started = packet.STATE.playing, true
  else
    self.manual_penalized = not self.manual_penalized
  end
end

function Controller:penalized()
  if self.gc_seen then return self.gc_penalized end
  return self.manual_penalized
end

-- The game as the game state machine reads it (Player/GameFSM/setplay.lua).
function Controller:view()
  return {
    team = self.team, kickoff_team = self.kickoff_team, our_kickoff = self.kickoff_team == self.team,
    dropball = self.kickoff_team == packet.DROPBALL,
    secondary = packet.SECONDARY[self.secondary_state] or 'normal',
    secondary_ours = self.secondary_team == self.team, secondary_mode = packet.MODES[self.secondary_mode],
    secondary_time = self.secondary_time, goalkeeper = self.goalkeeper, gc = self.gc_seen,
    first_half = self.first_half,
  }
end

function Controller:close()
  if self.sock then self.sock:close() self.sock = nil end
end

return M
