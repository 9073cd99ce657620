-- Scenario for the determinism test (run by ./run_repl in lockstep): reset, stance, a rolling ball,
-- a push, then prints the truth and some sensors as hex floats (bit-exact comparison).
-- luacheck: read globals Sim Body wait
local stance = dofile(os.getenv('HRP_ROOT') .. '/Tests/sim/stance.lua')
assert(Sim.reset())
stance.command(Body)
wait(1.0)
assert(Sim.teleport_ball(0.3, 0.05, 1.2, -0.1))
assert(Sim.push(6, -3, 0.15))
wait(2.0)
local t = Sim.truth()
local g = Body.get_gyro()
local a = Body.get_accelerometer()
print(string.format('truth %a %a %a %a %a %a fallen=%s', t.x, t.y, t.z, t.yaw, t.roll, t.pitch, tostring(t.fallen)))
print(string.format('ball %a %a %a %a %a', t.ball.x, t.ball.y, t.ball.z, t.ball.vx, t.ball.vy))
print(string.format('imu %a %a %a %a %a %a', g[1], g[2], g[3], a[1], a[2], a[3]))
print(string.format('tick %d time %.3f', Body.get_tick(), Body.get_time()))
print(string.format('readable x=%.4f y=%.4f yaw=%.4f ball=(%.3f, %.3f)', t.x, t.y, t.yaw, t.ball.x, t.ball.y))
