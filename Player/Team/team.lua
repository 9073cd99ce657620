-- Team communication: the league's standard message (Team.message, robocup.proto) broadcast on the
-- team's UDP port (Config/common/game.lua: team.port_base + team number) every `period` s of robot
-- time, and teammates' messages read back into a fixed table per player number. Another team's
-- messages (their colour), our own broadcasts heard back, and malformed ones (not a message, no
-- sender, a player number out of range, a pose or ball that is not finite) are ignored and counted,
-- and so are datagrams from a host not in `hosts` (when the config lists any); the socket hears
-- only the configured `interface`; at most `max_per_step` datagrams are read per step and the
-- table never grows past `max_players`.
--
--   local team = require('Team.team').new(cfg, opts)   -- cfg: team_number, player_number, team (game.lua)
--   team:update(t, me)        me = { pose = {x, y, a}, confidence, ball = {x, y, vx, vy} (field) or nil,
--                             penalised = bool, colour = 0/1 (GameController's) or nil, walk = {vx, vy, va},
--                             target = {x, y, a} (where it goes: the ball for the striker) or nil,
--                             fallen = bool (down: falling, lying, getting up; our extension field) }
--   team:mates(t)             teammates heard within lost_after s: list of { player, age, pose, ball,
--                             target (nil: none sent), fallen, ... }
--   team:publish(block)       the `team` shm block
local message = require('Team.message')
local udp = require('GameFSM.udp')

local M = {}
local Team = {}
Team.__index = Team

-- opts.port overrides the port, opts.socket: an open socket or false (tests feed receive()).
function M.new(cfg, opts)
  opts = opts or {}
  local tc = cfg.team
  local port = opts.port or (tc.port_base + cfg.team_number)
  local sock, err = opts.socket, nil
  if sock == nil then sock, err = udp.listen(port, tc.interface) end
  if sock == false then sock = nil end
  local self = setmetatable({
    cfg = tc, sock = sock, socket_error = err, port = port, player = cfg.player_number,
    allowed = udp.allow(tc.hosts, 'game.lua team.hosts'),
    received = 0, foreign = 0, malformed = 0, own = 0, sent = 0, rejected = 0, next_send = -math.huge,
    colour = 0, slots = {},
  }, Team)
  for k = 1, tc.max_players do
    self.slots[k] = { player = k, t = nil, pose = { 0, 0, 0 }, ball = { 0, 0, 0, 0 }, ball_known = false,
      penalised = false, fallen = false, target = nil, target_xya = { 0, 0, 0 } }
  end
  return self
end

local TEAM_OF_COLOUR = { [0] = 'blue', [1] = 'red' } -- the GameController's fieldPlayerColour

local function finite(v, n)
  for i = 1, n do
    local x = v[i]
    if x ~= x or x == math.huge or x == -math.huge then return false end
  end
  return true
end

-- A message the table can take: a sender in range, and a pose and ball of finite numbers (a NaN or
-- an infinity would spread from the table into the roles and the world model).
local function usable(m, max_players)
  if not m or not m.has_pose or m.player_id < 1 or m.player_id > max_players then return false end
  if m.pose and not finite(m.pose, 3) then return false end
  if m.target and m.target.pose and not finite(m.target.pose, 3) then return false end
  return not m.ball or (finite(m.ball, 2) and finite(m.ball_velocity, 2))
end

-- Takes one datagram at robot time t; true if it was a teammate's message.
function Team:receive(data, t)
  local m = message.decode(data)
  if not usable(m, self.cfg.max_players) then
    self.malformed = self.malformed + 1
    return false
  end
  local ours = self.colour and TEAM_OF_COLOUR[self.colour]
  if ours and m.team ~= 'unknown' and m.team ~= ours then
    self.foreign = self.foreign + 1
    return false
  end
  if m.player_id == self.player then self.own = self.own + 1 return false end
  local s = self.slots[m.player_id]
  s.t = t
  local p = m.pose or { 0, 0, 0 }
  s.pose[1], s.pose[2], s.pose[3] = p[1], p[2], p[3]
  s.ball_known = m.ball ~= nil
  if m.ball then
    s.ball[1], s.ball[2] = m.ball[1], m.ball[2]
    s.ball[3], s.ball[4] = m.ball_velocity[1], m.ball_velocity[2]
  end
  s.penalised = m.state == 'penalised'
  s.fallen = m.fallen
  local tp = m.target and m.target.pose
  if tp then s.target_xya[1], s.target_xya[2], s.target_xya[3] = tp[1], tp[2], tp[3] end
  s.target = tp and s.target_xya or nil
  self.received = self.received + 1
  return true
end

-- Our message from the world model's view (stamped with the wall clock's seconds: for other
-- teams' logs; nothing here steers by it).
local function encode(self, me)
  local team = self.colour and TEAM_OF_COLOUR[self.colour] or 'unknown'
  return message.encode({
    stamp = { os.time(), 0 }, player_id = self.player, team = team,
    pose = me.pose, ball = me.ball and { me.ball[1], me.ball[2], 0 } or nil,
    ball_velocity = me.ball and { me.ball[3], me.ball[4], 0 } or nil, walk = me.walk,
    target = me.target and { player_id = self.player, team = team, pose = me.target } or nil,
    state = me.penalised and 'penalised' or 'unpenalised', fallen = me.fallen,
  })
end

function Team:update(t, me)
  self.colour = me.colour
  if self.sock then
    for _ = 1, self.cfg.max_per_step do
      local data, host = self.sock:receive()
      if not data then break end
      if self.allowed(host) then self:receive(data, t) else self.rejected = self.rejected + 1 end
    end
    if t >= self.next_send or t < self.next_send - self.cfg.period then -- due, or the clock restarted
      self.next_send = t + self.cfg.period
      if self.sock:send(encode(self, me), self.cfg.broadcast, self.port) then self.sent = self.sent + 1 end
    end
  end
end

-- Teammates heard within lost_after s of t (a fresh list; the slots are reused).
function Team:mates(t)
  local list = {}
  for _, s in ipairs(self.slots) do
    if s.t and t - s.t <= self.cfg.lost_after and t >= s.t then
      s.age = t - s.t
      list[#list + 1] = s
    end
  end
  return list
end

function Team:publish(block, t)
  block:write(function(b)
    b.received[0], b.foreign[0], b.malformed[0], b.own[0], b.sent[0], b.rejected[0] =
      self.received, self.foreign, self.malformed, self.own, self.sent, self.rejected
    for k = 1, math.min(#self.slots, block:count('time')) do
      local s, i = self.slots[k], k - 1
      b.time[i] = s.t or 0
      b.pose[3 * i], b.pose[3 * i + 1], b.pose[3 * i + 2] = s.pose[1], s.pose[2], s.pose[3]
      b.ball[4 * i], b.ball[4 * i + 1], b.ball[4 * i + 2], b.ball[4 * i + 3] =
        s.ball[1], s.ball[2], s.ball[3], s.ball[4]
      b.ball_known[i] = s.ball_known and 1 or 0
      b.penalised[i] = s.penalised and 1 or 0
      b.fresh[i] = (s.t and t - s.t <= self.cfg.lost_after and t >= s.t) and 1 or 0
    end
  end)
end

function Team:close()
  if self.sock then self.sock:close() self.sock = nil end
end

return M
