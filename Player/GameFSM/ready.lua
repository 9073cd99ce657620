-- Ready: walk to the role's kick-off position in the own half (Team.position.ready), looking around
-- to localize.
local nav = require('BodyFSM.nav')
local position = require('Team.position')

local M = {}

function M.entry(ctx)
  ctx.body:event('stop', ctx)
end

function M.update(ctx)
  local p = position.ready(ctx.role or 'striker', ctx.cfg.player_number, ctx.rules.roles, ctx.cfg.ready_pose)
  local tx, ty = ctx.world:to_robot(p[1], p[2])
  local ha = nav.wrap(p[3] - ctx.world.pose.a)
  local vx, vy, va, d = nav.go_to(ctx, tx, ty, ha)
  local tol = ctx.cfg.ready_tolerance
  if d < tol[1] and math.abs(ha) < tol[2] then ctx.act.stop() else ctx.act.walk(vx, vy, va) end
  ctx.head:update(ctx)
end

return M
