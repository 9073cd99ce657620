-- DIAGNOSTIC, never for play: the behavior process, unchanged, that also writes every world-model
-- input (odometry, IMU yaw, the vision detections, the game state) and the sim's truth at the same
-- step to $WORLD_RECORD, so that Tools/tune/replay_world.lua can run changed world models over
-- the same inputs offline and measure their pose error. Run as the behavior of a scoring run:
--   SCORE_BEHAVIOR=Tools/tune/behavior_record.lua WORLD_RECORD_DIR=DIR Tests/scenarios/score_test.sh ...
-- One line per step:
--   s t game odom_x odom_y odom_a imu_yaw frame ball(0|1) bx by nposts [px py]... true_x true_y true_yaw
local behavior = require('Behavior.behavior')
local Sim = require('Sim')

local dir = assert(os.getenv('WORLD_RECORD_DIR'), 'WORLD_RECORD_DIR not set')
local out = assert(io.open(string.format('%s/record_%s.txt', dir, os.getenv('HRP_SEED') or 'x'), 'a'))
out:write('# s t game odom_x odom_y odom_a imu_yaw frame ball bx by nposts [px py]... true_x true_y true_yaw\n')

local b = behavior.new()
local world = b.world
local update = world.update
function world.update(w, t, odom, vis, imu_yaw)
  local T = Sim.truth()
  local parts = { string.format('s %.4f %s %.5f %.5f %.5f %.5f %d %d %.4f %.4f %d', t,
    b.game:state() or '-', odom[1], odom[2], odom[3], imu_yaw or 0, vis and vis.frame or -1,
    vis and vis.ball_detected and 1 or 0, vis and vis.ball[1] or 0, vis and vis.ball[2] or 0,
    vis and #vis.posts or 0) }
  for _, p in ipairs(vis and vis.posts or {}) do parts[#parts + 1] = string.format('%.4f %.4f', p[1], p[2]) end
  parts[#parts + 1] = string.format('%.4f %.4f %.4f', T.x, T.y, T.yaw)
  out:write(table.concat(parts, ' '), '\n')
  return update(w, t, odom, vis, imu_yaw)
end
b:run()
