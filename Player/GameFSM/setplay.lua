-- What the rules allow in PLAYING right now, from the GameController's view (controller:view())
-- and the rules' numbers (Config/common/game.lua):
--   'play'       the normal game (our kick-off, our set play once the referee says execute)
--   'keep_away'  the other team's kick-off or set play: stay `distance` m from the ball, face it
--   'take'       our set play before execute: go behind the ball towards the goal, do not kick
--   'stand'      stand and watch (placing, timeout, the other team's penalty shoot-out)
--   'guard'      our goalkeeper at the other team's penalty kick or shoot-out: on its goal line
--
--   local mode, distance = setplay.decide(view, rules, kickoff, role)   -- role: Team.roles'
--   kickoff = { since = s in PLAYING, ball_moved = bool }: the kick-off's progress (playing.lua)
local M = {}

local SET_PLAYS = { direct_free_kick = true, indirect_free_kick = true, penalty_kick = true,
  corner_kick = true, goal_kick = true, throw_in = true }
M.SET_PLAYS = SET_PLAYS
M.MODES = { 'play', 'keep_away', 'take', 'stand', 'guard' }
M.INDEX = { play = 0, keep_away = 1, take = 2, stand = 3, guard = 4 }

function M.decide(g, rules, kickoff, role)
  if not g.gc then return 'play' end -- no GameController: no referee to wait for
  local s = g.secondary
  if SET_PLAYS[s] then
    if g.secondary_ours then
      if g.secondary_mode == 'end' then return 'play' end
      if g.secondary_mode == 'placing' then return 'stand' end
      return 'take'
    end
    if s == 'penalty_kick' and role == 'goalkeeper' then return 'guard' end -- the rules' exception
    local d = rules.setplay.distance[s]
    if not d then error("game.lua: setplay.distance has no entry for '" .. s .. "'", 2) end
    return 'keep_away', d
  end
  if s == 'timeout' then return 'stand' end
  if s == 'penalty_shootout' then
    if g.our_kickoff then return 'play' end
    return role == 'goalkeeper' and 'guard' or 'stand'
  end
  -- normal play (and overtime): the other team's kick-off holds us back for a while
  if not g.our_kickoff and not g.dropball and kickoff and not kickoff.ball_moved
    and kickoff.since < rules.kickoff.wait then
    return 'keep_away', rules.kickoff.distance
  end
  return 'play'
end

return M
