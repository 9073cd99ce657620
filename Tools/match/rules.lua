-- The automatic referee's rules and clock (no I/O: Tools/match/referee.lua feeds it the sim's truth and
-- carries out what it returns). It plays a game by the numbers of Config/common/game.lua's
-- `referee` table on the sim's field (Config/platforms/Sim/sim.lua):
--   INITIAL -> READY (kick-off alternating) -> SET -> PLAYING; a goal: READY, the other team's kick-off;
--   the ball over a touch line: throw-in for the other team than the last to touch it, the ball on
--   the line; over a goal line: goal kick or corner kick, the ball placed; a robot fallen too long or
--   off the field: penalized, taken off, put back on its own half's touch line; half time (sides
--   change); FINISHED.
--
--   local m = match.new(rules, field, teams)  -- rules: game.referee; field: sim.lua's field/goal/ball;
--                                            -- teams: { { number = 1, players = { 1, 2 } }, {...} }
--   local acts = m:step(t, world)  -- world: { ball = {x, y, vx, vy}, score = {into +x, into -x},
--                                  --   robots = { { team = 1|2, player = k, x, y, roll, pitch, fallen } ... } }
--                                  -- acts: { { 'ball', x, y } | { 'robot', i, x, y, yaw } ... }
--   m:packet()  -- the GameController packet's fields for GameFSM/packet.lua's build()
--   m.stats, m.over, m.log (events: { t, text })
-- stats.falls counts a team's falls as the fall census does (Tools/match/census.lua's fell: the robot got
-- up between two falls) at every look, in every state, penalized or not: a team's falls add up to the
-- census's count of its robots.
local packet = require('GameFSM.packet')
local census = require('Tools.match.census')

local M = {}
local Match = {}
Match.__index = Match
local S = packet.STATE
local SECONDARY = { throw_in = 9, corner_kick = 7, goal_kick = 8 }
local abs, pi = math.abs, math.pi

function M.new(rules, field, teams)
  local tip = type(rules.census) == 'table' and rules.census.tip_angle or nil
  if type(tip) ~= 'number' or tip ~= tip or tip <= 0 then
    error('rules: referee.census.tip_angle (Config/common/game.lua) must be a number > 0, got '
      .. tostring(tip), 2)
  end
  local m = setmetatable({ r = rules, tip_angle = tip, down = {},
    L = field.length / 2, W = field.width / 2, goal_w = field.goal_width / 2,
    ball_r = field.ball_diameter / 2, penalty_mark = field.penalty_mark_distance,
    goal_area = { field.goal_area_length, field.goal_area_width / 2 },
    teams = teams, state = S.initial, first_half = 1, played = 0,
    kickoff = rules.first_kickoff, side = { 1, -1 }, score = { 0, 0 }, secondary = nil,
    robots = {}, over = false, log = {},
    stats = { goals = { 0, 0 }, own_goals = { 0, 0 }, falls = { 0, 0 }, penalties = { 0, 0 },
      throw_ins = 0, goal_kicks = 0, corners = 0 } }, Match)
  return m
end

function Match:event(text) self.log[#self.log + 1] = { self.t, text } end

function Match:enter(state)
  self.state, self.since = state, self.t
  self:event(packet.STATES[state])
end

-- Start positions: beside the own half's touch line at y = -W, facing into the field (as robots
-- enter a real field), or for a penalized robot's return: the touch line away from the ball.
function Match:start_pose(team, k)
  local s = self.side[team]
  return -s * (self.r.start_x + self.r.start_spacing * (k - 1)), -self.W, pi / 2
end

function Match:return_pose(team, ball)
  local y = (ball and ball[2] > 0) and -self.W or self.W
  return -self.side[team] * (self.L - self.penalty_mark), y, y > 0 and -pi / 2 or pi / 2
end

function Match:place_all(acts, world)
  for i, rb in ipairs(world.robots) do
    local x, y, a = self:start_pose(rb.team, rb.player)
    acts[#acts + 1] = { 'robot', i, x, y, a }
    self.robots[i] = nil
  end
end

-- Who touched the ball last: the sim's contacts when the world has them (world.touch: the index of
-- the robot whose body touched the ball last, false for none since the ball was placed); without
-- them, the robot nearest to the ball (within `touch` m) when the ball's velocity changed by more than
-- rolling explains (`touch_dv` m/s per look).
function Match:watch_touch(world)
  if world.touch ~= nil then
    if world.touch then self.last_touch = world.robots[world.touch].team end
    return
  end
  local b = world.ball
  if self.ball_dv < self.r.touch_dv then return end
  local best, bd = nil, self.r.touch
  for i, rb in ipairs(world.robots) do
    local d = math.sqrt((rb.x - b[1]) ^ 2 + (rb.y - b[2]) ^ 2)
    if d < bd and not (self.robots[i] and self.robots[i].penalty) then best, bd = rb.team, d end
  end
  if best then self.last_touch = best end
end

function Match:restart(acts, kind, team, x, y)
  local key = kind == 'throw_in' and 'throw_ins' or kind == 'goal_kick' and 'goal_kicks' or 'corners'
  self.stats[key] = self.stats[key] + 1
  self.secondary = { kind = kind, team = team, since = self.t, mode = 0, ball = { x, y } }
  acts[#acts + 1] = { 'ball', x, y }
  self:event(string.format('%s for team %d at (%.2f, %.2f)', kind, self.teams[team].number, x, y))
end

-- The ball out of the field: which restart, for which team, where.
function Match:ball_out(acts, b)
  local L, W, r = self.L, self.W, self.ball_r
  local last = self.last_touch or 1
  if abs(b[2]) > W + r then
    local x = math.max(-L + 0.5, math.min(L - 0.5, b[1]))
    self:restart(acts, 'throw_in', 3 - last, x, b[2] > 0 and W or -W)
    return true
  end
  if abs(b[1]) > L + r then
    local sx, sy = b[1] > 0 and 1 or -1, b[2] > 0 and 1 or -1
    local defending = self.side[1] == sx and 2 or 1      -- the team whose goal line it is
    if last ~= defending then
      self:restart(acts, 'goal_kick', defending, sx * (L - self.goal_area[1]), sy * self.goal_area[2])
    else
      self:restart(acts, 'corner_kick', 3 - defending, sx * L, sy * W)
    end
    return true
  end
  return false
end

function Match:penalize(acts, i, rb, why)
  local p = { penalty = true, until_t = self.t + self.r.penalty_time }
  self.robots[i] = p
  self.stats.penalties[rb.team] = self.stats.penalties[rb.team] + 1
  -- off the field while penalized: beside the touch line, out of play
  acts[#acts + 1] = { 'robot', i, -self.side[rb.team] * (1.0 + 0.5 * rb.player), -(self.W + self.r.off_field), pi / 2 }
  self:event(string.format('team %d player %d penalized (%s)', self.teams[rb.team].number, rb.player, why))
end

-- Lying too long and leaving the field; penalties that have run out.
function Match:watch_robots(acts, world)
  for i, rb in ipairs(world.robots) do
    local p = self.robots[i] or {}
    self.robots[i] = p
    if p.penalty then
      if self.t >= p.until_t then
        local x, y, a = self:return_pose(rb.team, world.ball)
        acts[#acts + 1] = { 'robot', i, x, y, a }
        self.robots[i] = {}
        self:event(string.format('team %d player %d back', self.teams[rb.team].number, rb.player))
      end
    else
      -- the penalty's clock: since the sim's fallen flag switched on
      if rb.fallen and not p.fallen_at then p.fallen_at = self.t
      elseif not rb.fallen then p.fallen_at = nil end
      local out = self.r.outside
      if abs(rb.x) > self.L + out or abs(rb.y) > self.W + out then
        self:penalize(acts, i, rb, 'left the field')
      elseif p.fallen_at and self.t - p.fallen_at > self.r.fallen_time then
        self:penalize(acts, i, rb, 'fallen')
      end
    end
  end
end

-- Falls, as the census counts them (one per lying: up between falls).
function Match:count_falls(world)
  for i, rb in ipairs(world.robots) do
    local fell
    fell, self.down[i] = census.fell(self.down[i], rb, self.tip_angle)
    if fell then self.stats.falls[rb.team] = self.stats.falls[rb.team] + 1 end
  end
end

function Match:playing(acts, world)
  self.played = self.played + self.dt
  local into = self.into
  if into then
    local scorer = self.side[1] == into and 1 or 2
    self.score[scorer] = self.score[scorer] + 1
    self.stats.goals[scorer] = self.stats.goals[scorer] + 1
    local own = self.last_touch == 3 - scorer
    if own then self.stats.own_goals[3 - scorer] = self.stats.own_goals[3 - scorer] + 1 end
    self:event(string.format('goal for team %d%s: %d:%d', self.teams[scorer].number, own and ' (own goal)' or '',
      self.score[1], self.score[2]))
    self.kickoff, self.secondary, self.last_touch = 3 - scorer, nil, nil
    acts[#acts + 1] = { 'ball', 0, 0 }
    self:enter(S.ready)
    return
  end
  self:watch_touch(world)
  local sp = self.secondary
  if sp then
    local moved = math.sqrt((world.ball[1] - sp.ball[1]) ^ 2 + (world.ball[2] - sp.ball[2]) ^ 2)
    if sp.mode == 0 and self.t - sp.since >= self.r.setplay_prepare then
      sp.mode, sp.since = 2, self.t
    elseif sp.mode == 2 and (moved > self.r.ball_moved or self.t - sp.since >= self.r.setplay_execute) then
      self.secondary = nil
    elseif sp.mode == 0 and moved > self.r.ball_moved then
      acts[#acts + 1] = { 'ball', sp.ball[1], sp.ball[2] }   -- touched before execute: put back
    end
  end
  if not self.secondary then self:ball_out(acts, world.ball) end
  self:watch_robots(acts, world)
  if self.played >= self.r.half_time then
    self:enter(S.finished)
    self.secondary = nil
    if self.first_half == 0 then self.over = true end
  end
end

function Match:step(t, world)
  self.dt = self.t and (t - self.t) or 0
  self.t = t
  self.index = world.robots
  -- a goal (the sim's count went up: into the goal at +x or -x) counts only in PLAYING
  local plus, minus = world.score[1], world.score[2]
  self.goals_seen = self.goals_seen or { plus, minus }
  self.into = (plus > self.goals_seen[1] and 1) or (minus > self.goals_seen[2] and -1) or nil
  self.goals_seen = { plus, minus }
  local v = { world.ball[3] or 0, world.ball[4] or 0 }
  self.ball_dv = self.ball_v and math.sqrt((v[1] - self.ball_v[1]) ^ 2 + (v[2] - self.ball_v[2]) ^ 2) or 0
  self.ball_v = v
  self:count_falls(world)
  local acts, r = {}, self.r
  if not self.since then -- the first look: everyone beside the touch line
    self.since = t
    self:place_all(acts, world)
  end
  local dt = t - self.since
  if self.state == S.initial and dt >= r.initial_time then
    acts[#acts + 1] = { 'ball', 0, 0 }
    self:enter(S.ready)
  elseif self.state == S.ready and dt >= r.ready_time then
    self:enter(S.set)
  elseif self.state == S.set and dt >= r.set_time then
    self:enter(S.playing)
  elseif self.state == S.playing then
    self:playing(acts, world)
  elseif self.state == S.finished and not self.over and dt >= r.break_time then
    -- half time: the teams change ends, the other team kicks off, everyone back beside the touch line
    self.first_half, self.side, self.played = 0, { -1, 1 }, 0
    self.kickoff, self.last_touch = 3 - r.first_kickoff, nil
    self:place_all(acts, world)
    self:enter(S.initial)
  end
  return acts
end

function Match:packet()
  local teams = {}
  for i, team in ipairs(self.teams) do
    local players = {}
    for _, n in ipairs(team.players) do players[n] = { goalkeeper = (n == self.r.goalkeeper) and 1 or 0 } end
    for j, rb in ipairs(self.index or {}) do
      local p = self.robots[j]
      if rb.team == i and p and p.penalty then
        players[rb.player].penalty = self.r.penalty_code
        players[rb.player].secs_till_unpenalised = math.max(0, math.ceil(p.until_t - self.t))
      end
    end
    teams[i] = { number = team.number, colour = i - 1, score = self.score[i], players = players }
  end
  local sp = self.secondary
  local remaining = self.r.half_time - self.played
  return { state = self.state, first_half = self.first_half, kickoff_team = self.teams[self.kickoff].number,
    players_per_team = #self.teams[1].players,
    secondary_state = sp and SECONDARY[sp.kind] or 0,
    secondary_state_info = sp and { self.teams[sp.team].number, sp.mode, 0, 0 } or { 0, 0, 0, 0 },
    secondary_time = sp and math.max(0, math.ceil((sp.mode == 0 and self.r.setplay_prepare or self.r.setplay_execute)
      - (self.t - sp.since))) or 0,
    secs_remaining = math.max(0, math.floor(remaining)), teams = teams }
end

return M
