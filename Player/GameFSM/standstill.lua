-- Standing still, head straight ahead, the body and head machines stopped: the initial and the
-- penalized states (standstill.new(kind)). Leaving either, the robot may have been carried (placed
-- for the game, put back after a penalty): the pose belief restarts from the placement's prior
-- (World.world reset_pose: the own half, or its touch lines facing in).
local M = {}

-- A state table for `kind` ('initial' or 'penalized': where the robot is put back differs).
function M.new(kind)
  return {
    entry = M.entry, update = M.update,
    exit = function(ctx)
      if ctx.world and ctx.world.reset_pose then
        ctx.world:reset_pose(kind == 'penalized', ctx.game and ctx.game.first_half ~= 0)
      end
    end,
  }
end

function M.entry(ctx)
  ctx.body:event('stop', ctx)
  ctx.head:event('reset', ctx)
end

function M.update(ctx)
  ctx.act.stop()
  ctx.act.head(0, 0)
end

return M
