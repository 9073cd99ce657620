-- The other team's free kick and kick-off in the simulator (run by ./run_repl inside the sim's
-- lockstep, setplay_test.sh): a test GameController (Tests/game/gc_sim.lua) sends the packets,
-- the robot's return packets are read back. Prints "check NAME ok|FAIL detail" lines.
--   ./run_repl Tests/game/setplay_play.lua GC_PORT RETURN_PORT
-- luacheck: globals Sim wait arg Body game
local packet = require('GameFSM.packet')
local gc_sim = require('Tests.game.gc_sim')
local Config = require('Config')

local port, rport = tonumber(arg[1]), tonumber(arg[2])
assert(port and rport, 'usage: setplay_play.lua GC_PORT RETURN_PORT')
local me = Config.load('behavior')
local rules = Config.load('game')
local gc = gc_sim.new(port, rport, me.team_number)
local OTHER = gc_sim.OTHER

local function check(name, ok, detail)
  print(string.format('check %s %s %s', name, ok and 'ok' or 'FAIL', detail))
  io.stdout:flush()
end
local function run(seconds, every)
  local t0, ok = Body.get_time(), true
  while Body.get_time() - t0 < seconds do
    gc:tick()
    wait(0.05)
    if every and not every() then ok = false end
  end
  return ok
end
local function dist()
  local T = Sim.truth()
  return math.sqrt((T.x - T.ball.x) ^ 2 + (T.y - T.ball.y) ^ 2), T
end

gc_sim.joined(4)
-- 1. the other team's direct free kick, the ball 0.45 m in front of the robot
Sim.teleport_robot(-1.5, 0.0, 0.0)
Sim.teleport_ball(-1.05, 0.0)
gc:set({ state = packet.STATE.playing, kickoff_team = OTHER, secondary_state = 4,
  secondary_state_info = { OTHER, 0, 0, 0 } })
local d0 = dist()
run(12)
local d, T = dist()
local need = rules.setplay.distance.direct_free_kick
check('free_kick_distance', d >= need and math.abs(T.ball.x + 1.05) < 0.05,
  string.format('robot-ball %.2f m after 12 s (from %.2f; rule %.2f), ball at (%.2f, %.2f), fallen=%s',
    d, d0, need, T.ball.x, T.ball.y, tostring(T.fallen)))
-- execute for them: we still keep away while the set play lasts
gc:set({ state = packet.STATE.playing, kickoff_team = OTHER, secondary_state = 4,
  secondary_state_info = { OTHER, 2, 0, 0 } })
local kept = run(3, function() return dist() >= need - 0.1 end)
check('free_kick_execute', kept, string.format('robot-ball %.2f m', (dist())))
-- over: play on, the robot goes for the ball
gc:set({ state = packet.STATE.playing, kickoff_team = OTHER })
local t0, reached = Body.get_time(), nil
run(20, function()
  if not reached and dist() < 0.4 then reached = Body.get_time() - t0 end
  return true
end)
check('play_on', reached ~= nil, string.format('at the ball after %s s', tostring(reached)))

-- 2. the other team's kick-off: ball on the centre spot, robot outside the circle facing it
gc:set({ state = packet.STATE.set, kickoff_team = OTHER })
Sim.teleport_robot(-1.0, 0.0, 0.0)
Sim.teleport_ball(0.0, 0.0)
run(2)
gc:set({ state = packet.STATE.playing, kickoff_team = OTHER })
local held = run(rules.kickoff.wait - 1.0, function() return dist() >= rules.kickoff.distance end)
check('kickoff_wait', held and game.setplay[0] == 1,
  string.format('robot-ball %.2f m, setplay %d', (dist()), game.setplay[0]))
t0, reached = Body.get_time(), nil
local names, last = require('BodyFSM.machine').states, -1
run(20, function()
  local dd, Tb = dist()
  local moved = math.abs(Tb.ball.x) + math.abs(Tb.ball.y) > 0.1
  if not reached and (dd < 0.4 or moved) then reached = Body.get_time() - t0 end
  if Body.get_time() - last >= 1 then
    last = Body.get_time()
    local Tr = Sim.truth()
    print(string.format('t=%.1f body=%s setplay=%d robot=(%.2f,%.2f) ball=(%.2f,%.2f)', last - t0,
      names[game.body_state[0] + 1], game.setplay[0], Tr.x, Tr.y, Tr.ball.x, Tr.ball.y))
  end
  return true
end)
check('kickoff_then_play', reached ~= nil,
  string.format('at the ball (or it moved) %s s after the wait', tostring(reached)))

-- 3. return packets: alive about once a second of robot time, all fields
local r = gc:returns()
local sim_s = Body.get_time()
local alive, good = 0, true
for _, p in ipairs(r) do
  if p.message == packet.MSG.alive then alive = alive + 1 end
  if p.version ~= 2 or p.team ~= me.team_number or p.player ~= me.player_number then good = false end
end
check('return_packets', good and alive > 0, string.format('%d alive packets in %.0f s of robot time', alive, sim_s))
