-- Where each role stands while it does not play the ball (Player/Team/roles.lua), on the field
-- (own goal at x = -length/2); nil: play the ball (the striker, unless the goalkeeper is clearing;
-- the goalkeeper while it clears). Numbers: Config/common/game.lua roles.
--   local x, y = position.target(role, ball, cfg, field, clearing)   -- ball: {x, y} on the field or nil
--   clearing: the goalkeeper plays the ball (roles.assign's third result)
--   local pose = position.ready(role, player, cfg, striker_pose) -- the kick-off position in READY
local M = {}

local sqrt = math.sqrt

local function clamp(x, lo, hi) if x < lo then return lo elseif x > hi then return hi end return x end

function M.target(role, ball, cfg, field, clearing)
  local gx = -field.length / 2
  local margin = cfg.field_margin
  if role == 'striker' and clearing and ball then
    -- upfield of the ball, towards the centre: where the clearance goes, out of the goalkeeper's way
    return clamp(ball[1] + cfg.receive_ahead, gx + margin, field.length / 2 - margin),
      clamp(ball[2] * cfg.receive_inside, -field.width / 2 + margin, field.width / 2 - margin)
  end
  if role == 'striker' then return nil end
  if role == 'goalkeeper' then
    if clearing then return nil end
    if not ball then return gx + cfg.keeper_depth, 0 end
    local dx, dy = ball[1] - gx, ball[2]
    local d = sqrt(dx * dx + dy * dy)
    -- on the line from the goal's centre to the ball, keeper_depth out, within the goal's width; never
    -- nearer the goal line than keeper_min_depth (a ball on the line: beside it, not walking into it)
    return gx + math.max(cfg.keeper_min_depth, cfg.keeper_depth * dx / d),
      clamp(cfg.keeper_depth * dy / d, -field.goal_width / 2, field.goal_width / 2)
  end
  if role == 'defender' then
    if not ball then return gx + cfg.defender_home, 0 end
    -- on the line from the own goal's centre to the ball, defender_gap m short of the ball (where a
    -- ball dribbled or bouncing towards the goal comes), never nearer the goal than keeper_depth.
    -- (A defender standing at a fixed fraction of the way lets opponents dribble past it.)
    local dx, dy = ball[1] - gx, ball[2]
    local d = sqrt(dx * dx + dy * dy)
    if d < 1e-6 then return gx + cfg.keeper_depth, 0 end
    local r = math.max(d - cfg.defender_gap, math.min(d, cfg.keeper_depth))
    return clamp(gx + r * dx / d, gx + margin, field.length / 2 - margin),
      clamp(r * dy / d, -field.width / 2 + margin, field.width / 2 - margin)
  end
  -- supporter: behind the ball, to the side nearer the field's centre line
  if not ball then return cfg.supporter_home, 0 end
  local side = ball[2] > 0 and -1 or 1
  return clamp(ball[1] - cfg.supporter_back, gx + margin, field.length / 2 - margin),
    clamp(ball[2] + side * cfg.supporter_side, -field.width / 2 + margin, field.width / 2 - margin)
end

function M.ready(role, player, cfg, striker_pose)
  if role == 'striker' then return striker_pose end
  local p = cfg.ready[role]
  if role == 'supporter' and player % 2 == 1 then return { p[1], -p[2], p[3] } end
  return p
end

return M
