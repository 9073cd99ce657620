-- The other team's free kick and kick-off in the simulator (run by ./run_repl inside the sim's
-- lockstep, setplay_test.sh): a test GameController (Tests/game/gc_sim.lua) sends the packets,
-- the robot's return packets are read back (alive, the chest button). Prints "check NAME ok|FAIL detail" lines.
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
local t_first = Body.get_time()
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

-- 2. the other team's kick-off: the robot placed in its half walks to its kick-off position in READY
-- (localizing on the way), stands in SET; the ball on the centre spot
-- (placed by hand in INITIAL: leaving it, the robot localizes afresh)
gc:set({ state = packet.STATE.initial, kickoff_team = OTHER })
run(1)
Sim.teleport_robot(-2.5, 0.5, 0.0)
Sim.teleport_ball(0.0, 0.0)
run(1)
gc:set({ state = packet.STATE.ready, kickoff_team = OTHER })
run(15)
gc:set({ state = packet.STATE.set, kickoff_team = OTHER })
run(2)
gc:set({ state = packet.STATE.playing, kickoff_team = OTHER })
local held = run(rules.kickoff.wait - 1.0, function() return dist() >= rules.kickoff.distance end)
check('kickoff_wait', held and game.setplay[0] == 1,
  string.format('robot-ball %.2f m, setplay %d', (dist()), game.setplay[0]))
-- after the wait: the rules let it play (body machine running) and it goes (moves or moves the ball)
local names = require('BodyFSM.machine').states
run(1.5)
local body = names[game.body_state[0] + 1]
local T0 = Sim.truth()
t0, reached = Body.get_time(), nil
run(20, function()
  local Tn = Sim.truth()
  local walked = math.sqrt((Tn.x - T0.x) ^ 2 + (Tn.y - T0.y) ^ 2) > 0.3
  local moved = math.abs(Tn.ball.x) + math.abs(Tn.ball.y) > 0.1
  if not reached and (walked or moved) then reached = Body.get_time() - t0 end
  return true
end)
check('kickoff_then_play', game.setplay[0] == 0 and body ~= 'idle' and reached ~= nil,
  string.format('after the wait: setplay %d, body %s; walked 0.3 m or moved the ball %s s later', game.setplay[0],
    tostring(body), tostring(reached)))

-- 3. the chest button: reported to the GameController, whose packets decide
gc:returns()
local function pressed_message()
  Sim.press_button(1, 0.2)
  run(0.6)
  for _, p in ipairs(gc:returns()) do
    if p.message ~= packet.MSG.alive then return p end
  end
end
local p1 = pressed_message()
local still_playing = game.penalized[0] == 0
gc.penalty = 34 -- the GameController's answer: penalised (HL_PICKUP_OR_INCAPABLE)
run(1)
local penalised = game.penalized[0] == 1 and game.state[0] == packet.STATE.playing
local p2 = pressed_message()
check('button', p1 and p1.message == packet.MSG.man_penalise and p1.team == me.team_number
  and p1.player == me.player_number and still_playing and penalised and p2
  and p2.message == packet.MSG.man_unpenalise,
  string.format('first press: message %s (playing on: %s); penalised by the packets: %s; second press: message %s',
    p1 and p1.message or 'none', tostring(still_playing), tostring(penalised), p2 and p2.message or 'none'))
gc.penalty = nil

-- 4. return packets: alive about once a second of robot time from the first packet on, all fields
gc:returns()
local sim_s = Body.get_time() - t_first
local alive, good = 0, true
for _, p in ipairs(gc.log) do
  if p.message == packet.MSG.alive then alive = alive + 1 end
  if p.bad or p.version ~= 2 or p.team ~= me.team_number or p.player ~= me.player_number then good = false end
end
check('return_packets', good and alive >= 0.9 * sim_s - 1 and alive <= 1.1 * sim_s + 1,
  string.format('%d alive packets in %.1f s of robot time, %d return packets in all, all well-formed: %s',
    alive, sim_s, #gc.log, tostring(good)))
