-- What the behavior specs feed the behavior process for one step (24 ms: three 8 ms ticks): the
-- clock, and a vision frame with the ball at (bx, by) (robot frame, m) and the opponent goal's posts
-- as seen from (-2, 0) facing them (the robot attacks only once it knows where it is).
--   tick = view.frame(sensor, vision, tick, bx, by)
local M = {}

function M.frame(sensor, vision, tick, bx, by)
  tick = tick + 3
  sensor.tick[0] = tick
  sensor.time[0] = sensor.time[0] + 0.024
  vision.frame[0] = vision.frame[0] + 1
  vision.time[0] = sensor.time[0]
  vision.ball_detected[0] = 1
  vision.ball_position[0], vision.ball_position[1] = bx, by
  vision.goal_posts[0] = 2
  vision.goal_position[0], vision.goal_position[1] = 6.5, 1.3
  vision.goal_position[2], vision.goal_position[3] = 6.5, -1.3
  return tick
end

return M
