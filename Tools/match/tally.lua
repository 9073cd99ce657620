-- Per-robot figures of a refereed match (no I/O: Tools/match/referee.lua feeds it each look): seconds of
-- PLAYING in each role (the robot's own `game.role`), seconds its pose belief was the mirror of the
-- truth (the two goals look alike: the belief near (-x, -y) of where the robot really is), falls (as the
-- fall census counts them: Tools/match/census.lua's fell, up between two falls) and penalties.
--
--   local tally = require('Tools.match.tally').new(robots, tip_angle)  -- robots: { { team, player } ... };
--                                            -- tip_angle: game.lua's referee.census.tip_angle (rad)
--   tally:look(dt, playing, i, truth, belief, side, penalized)
--     truth: { x, y, roll, pitch, fallen } (field frame); belief: { x, y, role } in the team's frame (x towards
--     the opponent goal) or nil; side: the match's side of the robot's team (1: own goal at -x)
--   tally:lines()  -- one line per robot: "tally T/P striker=... mirrored=... falls=N penalties=N"
local census = require('Tools.match.census')

local M = {}

local ROLES = { 'striker', 'supporter', 'defender', 'goalkeeper' }
M.ROLES = ROLES
-- a belief counts as mirrored when it is this far (m) from the truth and nearer the truth's mirror
-- by this margin: near the centre both are close and nothing is said
M.FAR, M.MARGIN = 1.5, 0.5

local Tally = {}
Tally.__index = Tally

function M.new(robots, tip_angle)
  if type(tip_angle) ~= 'number' or tip_angle ~= tip_angle or tip_angle <= 0 then
    error('tally: referee.census.tip_angle (Config/common/game.lua) must be a number > 0, got '
      .. tostring(tip_angle), 2)
  end
  local t = setmetatable({ robots = {}, tip_angle = tip_angle }, Tally)
  for i, r in ipairs(robots) do
    t.robots[i] = { team = r.team, player = r.player, role = {}, mirrored = 0, falls = 0, penalties = 0 }
    for _, name in ipairs(ROLES) do t.robots[i].role[name] = 0 end
  end
  return t
end

-- Whether a belief (field frame) is the mirror of the truth rather than the truth.
function M.mirrored(bx, by, tx, ty)
  local d = math.sqrt((bx - tx) ^ 2 + (by - ty) ^ 2)
  local dm = math.sqrt((bx + tx) ^ 2 + (by + ty) ^ 2)
  return d > M.FAR and dm + M.MARGIN < d
end

function Tally:look(dt, playing, i, truth, belief, side, penalized)
  local r = self.robots[i]
  local fell
  fell, r.down = census.fell(r.down, truth, self.tip_angle)
  if fell then r.falls = r.falls + 1 end
  if penalized and not r.was_penalized then r.penalties = r.penalties + 1 end
  r.was_penalized = penalized
  if not playing or penalized or not belief then return end
  local name = ROLES[belief.role]
  if name then r.role[name] = r.role[name] + dt end
  -- the team's frame to the field's: turned by pi when the team's own goal is at +x
  if M.mirrored(side * belief.x, side * belief.y, truth.x, truth.y) then r.mirrored = r.mirrored + dt end
end

function Tally:lines()
  local out = {}
  for _, r in ipairs(self.robots) do
    local parts = { string.format('tally %d/%d', r.team, r.player) }
    for _, name in ipairs(ROLES) do parts[#parts + 1] = string.format('%s=%.1f', name, r.role[name]) end
    parts[#parts + 1] = string.format('mirrored=%.1f falls=%d penalties=%d', r.mirrored, r.falls, r.penalties)
    out[#out + 1] = table.concat(parts, ' ')
  end
  return out
end

return M
