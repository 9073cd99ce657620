-- Writes a CSV trace of the walk generator alone (no robot): time, COM, ZMP, feet, swing height.
-- usage: luajit Tools/tune/walk_trace.lua OUT.csv vx vy va [seconds] [stop_at]
-- Plot: python3 Tools/plot/plot_walk.py OUT.csv OUT.png
local Config = require('Config')
local kin = require('kinematics')
local Walk = require('Motion.walk')

local out = arg[1] or 'walk.csv'
local vx, vy, va = tonumber(arg[2]) or 0.25, tonumber(arg[3]) or 0, tonumber(arg[4]) or 0
local seconds = tonumber(arg[5]) or 6
local stop_at = tonumber(arg[6]) or seconds - 1.5
local robot = Config.load('robot')
local w = Walk.new(Config.load('walk'), kin.load()):bind(robot)
local q = {}
for i = 1, #robot.joints do q[i] = 0 end
local dt = robot.period
w:set_velocity(vx, vy, va)
w:start()
local f = assert(io.open(out, 'w'))
f:write('t,com_x,com_y,zmp_x,zmp_y,lx,ly,la,rx,ry,ra,swing_z,active\n')
local n = math.floor(seconds / dt + 0.5)
for k = 1, n do
  if k * dt >= stop_at then w:stop() end
  w:advance(dt)
  w:joint_angles(q, nil, dt)
  w:update_com_offset(q)
  f:write(string.format('%.4f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%d\n', k * dt,
    w.com[1], w.com[2], w.zmp[1], w.zmp[2], w.uLeft[1], w.uLeft[2], w.uLeft[3],
    w.uRight[1], w.uRight[2], w.uRight[3], w.swing_z, w.active and 1 or 0))
end
f:close()
