-- What the vision process (Player/Vision/main.lua) sees, read from the `vision` block.
--
--   local Vision = require('Vision')
--   Vision.ball()        --> { detected = bool, x = m, y = m, t = s, u = px, v = px, radius = px, frame = n }
--   Vision.goal_posts()  --> { {x = m, y = m}, ... } (0 to 2 posts)
--   Vision.robots()      --> { {x = m, y = m, team = -1|0|1, u0, v0, u1, v1 = px}, ... } (0 to 4, nearest first)
-- Positions are in the robot frame (x forward, y left); t is the robot clock of the frame.
local shm = require('shm')

local M = {}

local block
local function vision()
  block = block or shm.open('vision')
  return block
end

-- The ball of the latest frame processed (x, y, u, v, radius only when detected).
function M.ball()
  local b = vision()
  return b:read(function(v)
    local res = { detected = v.ball_detected[0] ~= 0, t = v.time[0], frame = v.frame[0] }
    if res.detected then
      res.x, res.y = v.ball_position[0], v.ball_position[1]
      res.u, res.v = v.ball_image[0], v.ball_image[1]
      res.radius = v.ball_radius[0]
    end
    return res
  end)
end

-- The first items of the latest frame's list: count_field says how many (at most max), item(v, i)
-- makes the i-th from the block.
local function frame_list(count_field, max, item)
  return vision():read(function(v)
    local list = {}
    for i = 1, math.min(v[count_field][0], max) do list[i] = item(v, i) end
    return list
  end)
end

-- The goal posts of the latest frame.
function M.goal_posts()
  return frame_list('goal_posts', 2, function(v, i)
    return { x = v.goal_position[2 * i - 2], y = v.goal_position[2 * i - 1] }
  end)
end

-- Other robots of the latest frame: the foot point of each (x, y), the team colour seen (-1 unknown,
-- 0 blue, 1 red), its box in the image and whether its feet are in it (else its range is an upper bound).
function M.robots()
  return frame_list('robots', 4, function(v, i)
    local k = 4 * (i - 1)
    return { x = v.robot_position[2 * i - 2], y = v.robot_position[2 * i - 1], team = v.robot_team[i - 1],
             u0 = v.robot_image[k], v0 = v.robot_image[k + 1], u1 = v.robot_image[k + 2],
             v1 = v.robot_image[k + 3], foot_visible = v.robot_foot_visible[i - 1] ~= 0 }
  end)
end

-- Frames processed and the measured frame rate (frames per second of robot time).
function M.frame() return vision().frame[0], vision().fps[0] end

return M
