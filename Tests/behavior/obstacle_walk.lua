-- A robot walks to the ball with another robot standing in between (run by ./run_repl on the
-- walking robot's lockstep, obstacle_test.sh): the standing robot (no processes: its DCM holds the
-- body's safe pose) must be seen by the vision, kept in the world model as an obstacle and walked
-- around, the ball reached without touching it (the sim's truth: the distance between the two
-- torsos, whether the standing one moved or fell). Prints "check NAME ok|FAIL detail" lines.
--   ./run_repl Tests/behavior/obstacle_walk.lua
-- luacheck: globals Sim wait shm Body
local gc_sim = require('Tests.game.gc_sim')

local other = shm.robot_id() + 1
local sim2 = Sim.of(other)
local vision, world = shm.open('vision'), shm.open('world')

local function check(name, ok, detail)
  print(string.format('check %s %s %s', name, ok and 'ok' or 'FAIL', detail))
  io.stdout:flush()
end

gc_sim.joined(4)
-- the walker behind, the other robot 1 m ahead of it on the way, the ball 1 m beyond
Sim.teleport_robot(-2.2, 0.05, 0.0)
sim2.teleport_robot(-1.2, 0.0, math.pi)
Sim.teleport_ball(-0.2, 0.0)
wait(1.0)
local T2 = sim2.truth()
local x2, y2 = T2.x, T2.y
local t0 = Body.get_time()
local seen, remembered, min_d, reached, path = nil, 0, math.huge, nil, {}
local next_note = t0
while Body.get_time() - t0 < 70 do
  local T, U = Sim.truth(), sim2.truth()
  local d = math.sqrt((T.x - U.x) ^ 2 + (T.y - U.y) ^ 2)
  if d < min_d then min_d = d end
  -- the other robot in the walker's frame (its torso), against the vision's foot point
  local c, s = math.cos(-T.yaw), math.sin(-T.yaw)
  local rx, ry = c * (U.x - T.x) - s * (U.y - T.y), s * (U.x - T.x) + c * (U.y - T.y)
  for k = 1, vision.robots[0] do
    local e = math.sqrt((vision.robot_position[2 * k - 2] - rx) ^ 2 + (vision.robot_position[2 * k - 1] - ry) ^ 2)
    if e < 0.35 and (not seen or e < seen) then seen = e end
  end
  if world.obstacles[0] > remembered then remembered = world.obstacles[0] end
  local bd = math.sqrt((T.x - T.ball.x) ^ 2 + (T.y - T.ball.y) ^ 2)
  if bd < 0.35 and not reached then reached = Body.get_time() - t0 end
  if Body.get_time() >= next_note then
    next_note = next_note + 2
    local obs = {}
    for k = 1, world.obstacles[0] do
      obs[k] = string.format('%.1f,%.1f', world.obstacle[2 * k - 2], world.obstacle[2 * k - 1])
    end
    path[#path + 1] = string.format('(%.2f %.2f%s)', T.x, T.y,
      #obs > 0 and ' obstacles ' .. table.concat(obs, ' ') or '')
  end
  if reached and Body.get_time() - t0 > reached + 2 then break end
  wait(0.1)
end
local U = sim2.truth()
local moved = math.sqrt((U.x - x2) ^ 2 + (U.y - y2) ^ 2)
print('walker path (field) and obstacles (robot frame), every 2 s: ' .. table.concat(path, ' '))
check('seen', seen ~= nil and remembered > 0,
  string.format('the standing robot found by the vision within %s m of its truth; world obstacles up to %d',
    seen and string.format('%.2f', seen) or 'never', remembered))
check('reached_ball', reached ~= nil, string.format('the ball reached (0.35 m) after %s s',
  reached and string.format('%.1f', reached) or 'never'))
check('no_contact', min_d > 0.35 and moved < 0.05 and not U.fallen,
  string.format('torsos at least %.2f m apart; the standing robot moved %.3f m%s', min_d, moved,
    U.fallen and ', fell' or ''))
