-- Minimal Sim API over the `sim` shm block for the motion scenarios when Lib/Sim.lua is absent
-- (same calls: truth, reset, teleport_robot, teleport_ball, push). Requests are applied by the
-- sim DCM between ticks, also while it waits on lockstep participants.
local shm = require('shm')

local M = {}
local sim = shm.open('sim')

local function request(code, a, b, c, d)
  sim:write(function(s)
    s.request[0] = code
    s.args[0], s.args[1], s.args[2], s.args[3] = a or 0, b or 0, c or 0, d or 0
    s.request_seq[0] = s.request_seq[0] + 1
  end)
  local seq = sim.request_seq[0]
  local deadline = shm.C.shm_now() + 5
  while sim.done_seq[0] ~= seq do
    if shm.C.shm_now() > deadline then error('Sim: the simulator did not apply request ' .. code, 3) end
    shm.C.shm_futex_wait(sim.done_seq, sim.done_seq[0], 0.01)
  end
end

function M.truth()
  return sim:read(function(s)
    return {
      x = s.robot[0], y = s.robot[1], z = s.robot[2], yaw = s.robot[3], roll = s.robot[4], pitch = s.robot[5],
      fallen = s.fallen[0] ~= 0,
      ball = { x = s.ball[0], y = s.ball[1], z = s.ball[2], vx = s.ball[3], vy = s.ball[4] },
    }
  end)
end
function M.reset() request(1) end
function M.teleport_robot(x, y, yaw) request(2, x, y, yaw) end
function M.teleport_ball(x, y) request(3, x, y, 0, 0) end
function M.push(fx, fy, duration) request(4, fx, fy, duration) end

return M
