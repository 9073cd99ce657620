-- Roles from the shared estimates (Player/Team/team.lua): every robot computes the whole team's
-- assignment from the same data, so the robots agree without sending roles (the league's message
-- has no field for them). Among the robots playing (heard within lost_after, not penalised):
--   goalkeeper  the GameController's (or the site's) goalkeeper, once the team playing has
--               `keeper_team` robots (fewer: it plays in the field); if it is lost, the robot
--               nearest the own goal takes over
--   striker     the one that reaches the ball first (distance / speed plus the turn); the previous
--               assignment's striker keeps the role until another is faster by `striker_margin` s
--               (the same for every robot: with the margin on "me", two robots that both were
--               strikers once, e.g. before they heard each other, would both stay strikers for
--               good); a teammate that says it goes for the ball
--               (its message's target_pose at its ball) with a lower player number than that
--               striker takes the margin instead, so that two robots that disagree settle on one
--   defender    the one nearest the own goal among the rest
--   supporter   everyone else
-- A robot that is down (falling, lying or getting up: its message's `fallen`, our extension field)
-- reaches the ball `fallen_time` s later and keeps no margin, so an upright teammate near the ball
-- takes it over (a striker lying on the ground otherwise keeps the ball from a defender a metre away).
-- A robot alone is the striker. Two (keeper_team = 3) are a striker and a defender: a goalkeeper of
-- two leaves a lone striker against two, and its poor pose belief near the goal line walks it off
-- the field.
-- A ball within keeper_clear of the own goal's centre is the goalkeeper's to clear when it reaches
-- it first (the striker's margin kept while it clears); the striker then waits upfield for the
-- clearance (Team/position.lua) instead of both going for the ball and blocking each other.
--
--   local role, assignment, clearing = roles.assign(me, mates, cfg, ball, own_goal_x, previous, was_clearing)
--   me / mates: { player, pose = {x, y, a}, [target = {x, y, a}, ball = {x, y}, ball_known, fallen] }
--   ball: {x, y} on the field or nil; cfg: game.lua roles
--   previous: the last assignment ({ [player] = role }) or nil; its striker's margin counts only when
--   the same robots play (one joins or is lost: a fresh choice, which every robot makes alike)
--   clearing: the goalkeeper plays the ball now (was_clearing: it did at the last assignment)
local M = {}

local sqrt, atan2, abs = math.sqrt, math.atan2, math.abs

M.ROLES = { 'striker', 'supporter', 'defender', 'goalkeeper' }
M.INDEX = { striker = 1, supporter = 2, defender = 3, goalkeeper = 4 }

local function wrap(a) return (a + math.pi) % (2 * math.pi) - math.pi end

-- Seconds robot r needs to reach the ball: walking plus turning towards it.
function M.time_to_ball(r, ball, cfg)
  local dx, dy = ball[1] - r.pose[1], ball[2] - r.pose[2]
  local d = sqrt(dx * dx + dy * dy)
  return d / cfg.walk_speed + abs(wrap(atan2(dy, dx) - r.pose[3])) / cfg.turn_speed
end

local function goal_distance(r, own_goal_x)
  local dx, dy = r.pose[1] - own_goal_x, r.pose[2]
  return sqrt(dx * dx + dy * dy)
end

-- Picks from `list` the robot with the least key(r) (ties: the lower player number).
local function pick(list, key)
  local best, best_k
  for _, r in ipairs(list) do
    local k = key(r)
    if not best or k < best_k or (k == best_k and r.player < best.player) then best, best_k = r, k end
  end
  return best
end

local function remove(list, r)
  for i, x in ipairs(list) do if x == r then table.remove(list, i) return end end
end

-- The previous assignment's striker, when `previous` holds exactly the robots of `team`.
local function previous_striker(previous, team)
  if not previous then return nil end
  local n, striker = 0, nil
  for player, role in pairs(previous) do
    n = n + 1
    if role == 'striker' then striker = player end
  end
  if n ~= #team then return nil end
  for _, r in ipairs(team) do if not previous[r.player] then return nil end end
  return striker
end

-- Whether teammate r says it goes for the ball: the target in its message at its own ball.
local function striking(r, cfg)
  if r.fallen or not (r.target and r.ball_known) then return false end
  local dx, dy = r.target[1] - r.ball[1], r.target[2] - r.ball[2]
  return dx * dx + dy * dy < cfg.striking_radius * cfg.striking_radius
end

-- The assignment { [player] = role } and this robot's role.
function M.assign(me, mates, cfg, ball, own_goal_x, previous, was_clearing)
  local team = { me }
  for _, m in ipairs(mates) do if not m.penalised then team[#team + 1] = m end end
  local kept = previous_striker(previous, team)
  local out = {}
  -- the goalkeeper
  local keeper
  if cfg.goalkeeper ~= 0 and #team >= cfg.keeper_team then
    for _, r in ipairs(team) do if r.player == cfg.goalkeeper then keeper = r end end
    keeper = keeper or pick(team, function(r) return goal_distance(r, own_goal_x) end)
    out[keeper.player] = 'goalkeeper'
    remove(team, keeper)
  end
  -- the striker: first to the ball (without a ball anywhere: the one furthest forward); the margin
  -- for the previous striker or the lowest-numbered teammate that says it strikes
  for _, r in ipairs(team) do
    if r ~= me and striking(r, cfg) and (not kept or r.player < kept) then kept = r.player end
  end
  -- a teammate's time from the ball it reports (it sees it from there), so that every robot computes
  -- every time from the same numbers; with one ball for all, each robot's own ball estimate, 0.1 to
  -- 0.5 m apart, made two robots disagree on who was nearer (both or neither striking: 3-9% of a match)
  local function t_ball(r)
    local b = (r ~= me and r.ball_known and r.ball) or ball
    local tb = b and M.time_to_ball(r, b, cfg) or -r.pose[1]
    if r.fallen then return tb + cfg.fallen_time end
    if r.player == kept then tb = tb - cfg.striker_margin end
    return tb
  end
  local striker = pick(team, t_ball)
  local clearing = false
  if keeper and ball and goal_distance({ pose = ball }, own_goal_x) < cfg.keeper_clear then
    local tk = M.time_to_ball(keeper, ball, cfg) - (was_clearing and cfg.striker_margin or 0)
    clearing = not striker or tk < M.time_to_ball(striker, ball, cfg)
  end
  if striker then out[striker.player] = 'striker' remove(team, striker) end
  local defender = pick(team, function(r) return goal_distance(r, own_goal_x) end)
  if defender then out[defender.player] = 'defender' remove(team, defender) end
  for _, r in ipairs(team) do out[r.player] = 'supporter' end
  return out[me.player], out, clearing
end

return M
