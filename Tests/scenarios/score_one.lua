-- One scoring run, run by ./run_repl inside the sim's lockstep (see score_test.sh):
--   ./run_repl Tests/scenarios/score_one.lua SEED LIMIT_S [KILL_VISION_AT_S]
-- Places robot and ball from SEED (both anywhere in the own half, any heading), lets the robot play
-- and prints one line: "result seed=N goal=1 time=T" (or goal=0) plus where things ended.
-- luacheck: globals Sim wait arg shm Body world game vision
local seed, limit, kill_at = tonumber(arg[1]), tonumber(arg[2] or '120'), tonumber(arg[3] or '')
assert(seed and limit, 'usage: score_one.lua SEED LIMIT_S [KILL_VISION_AT_S]')

-- the start configuration from the seed (its own generator: independent of everything else)
local s = seed * 7919 + 17
local function rnd()
  s = (s * 1103515245 + 12345) % 2147483648
  return s / 2147483648
end
local rx, ry, ryaw = -4.2 + 3.9 * rnd(), -2.7 + 5.4 * rnd(), -math.pi + 2 * math.pi * rnd()
local bx, by
repeat
  bx, by = -4.0 + 3.7 * rnd(), -2.5 + 5.0 * rnd()
until (bx - rx) ^ 2 + (by - ry) ^ 2 > 0.5 ^ 2

-- wait until the robot's processes take part in the lockstep (motion, vision, behavior)
local participants = require('Tests.scenario_lib').participants
local sync = shm.open('sync')
local deadline = os.time() + 60
while true do
  if participants(sync) >= 4 then break end -- them and this script
  if os.time() > deadline then error('the robot processes did not join the lockstep within 60 s') end
  -- a process that has joined holds the clock until its first step, which may take a few seconds
  -- of start-up on a loaded machine: wait() then reports a stopped clock, and we try again
  local ok, err = pcall(wait, 0.1)
  if not ok and not tostring(err):find('not advancing', 1, true) then error(err, 0) end
end

Sim.teleport_robot(rx, ry, ryaw)
Sim.teleport_ball(bx, by)
wait(0.1)
local plus0, minus0 = Sim.score()
local t0 = Body.get_time()
print(string.format('start seed=%d robot=(%.2f,%.2f,%.2f) ball=(%.2f,%.2f)', seed, rx, ry, ryaw, bx, by))
io.stdout:flush()

-- the pid of the vision process run_main started last (from run_main's log, $MAIN_LOG)
local function vision_pid()
  local f = io.open(os.getenv('MAIN_LOG') or '', 'r')
  if not f then return nil end
  local pid
  for line in f:lines() do pid = tonumber(line:match('vision started %(pid (%d+)%)')) or pid end
  f:close()
  return pid
end

local ffi = require('ffi')
ffi.cdef('int kill(int pid, int sig);')
local killed = false
local goal, own = false, false
-- optional trace ($TRUTH_LOG): truth, world model and states every step, for plotting
-- (Tools/plot/plot_paths.py)
local trace = os.getenv('TRUTH_LOG') and io.open(os.getenv('TRUTH_LOG'), 'w')
local body_names = require('BodyFSM.machine').states or {}
local head_names = require('HeadFSM.machine').states or {}
local function log_step()
  if not trace then return end
  local T = Sim.truth()
  local ok, mstate = pcall(function() return require('Motion').state() end)
  local Walk = require('Walk')
  local cx, cy, ca = Walk.get_velocity()
  local wx, wy, wa = Walk.velocity()
  trace:write(string.format('%.2f %.3f %.3f %.3f %.3f %.3f %d %.3f %.3f %.3f %.3f %.3f %.1f %s %s %.2f %s'
    .. ' %.3f %.3f %.3f %.3f %.3f %.3f\n',
    Body.get_time() - t0, T.x, T.y, T.yaw, T.ball.x, T.ball.y, T.fallen and 1 or 0,
    world.pose[0], world.pose[1], world.pose[2], world.ball[0], world.ball[1],
    Body.get_time() - world.ball_time[0], body_names[game.body_state[0] + 1] or tostring(game.body_state[0]),
    ok and tostring(mstate) or '?', world.pose_confidence[0],
    head_names[game.head_state[0] + 1] or tostring(game.head_state[0]), cx, cy, ca, wx, wy, wa))
  for i = 0, math.min(2, vision.goal_posts[0]) - 1 do
    trace:write(string.format('post %.2f %.3f %.3f\n', Body.get_time() - t0, vision.goal_position[2 * i],
      vision.goal_position[2 * i + 1]))
  end
end
if trace then
  trace:write('# t x y yaw bx by fallen px py pyaw wbx wby ball_age body motion confidence head'
    .. ' cmd_vx cmd_vy cmd_va walk_vx walk_vy walk_va\n')
end
-- optional capture log ($CAPTURE_LOG): the walk's capture point error every motion tick, to see
-- what normal play gives (Tools/plot/capture_stats.py): t ex ey walking motion-state
local cap_path = os.getenv('CAPTURE_LOG') or ''
local cap = cap_path ~= '' and assert(io.open(cap_path, 'w'))
local motion = cap and shm.open('motion')
local period = cap and require('Config').load('robot').period
local function wait_quarter()
  if not cap then return wait(0.25) end
  local t1 = Body.get_time() + 0.25
  while Body.get_time() < t1 - 1e-6 do
    wait(period)
    cap:write(string.format('%.3f %.4f %.4f %d %d\n', Body.get_time() - t0, motion.capture_error[0],
      motion.capture_error[1], motion.walking[0], motion.state[0]))
  end
end
if cap then cap:write('# t ex ey walking state\n') end
-- optional frames ($FRAME_DIR): the camera's frame as a PNG every $FRAME_EVERY s (default 5) of play,
-- the vision's ball circled in red: frame_T.png, and a line per frame in $FRAME_DIR/frames.txt
-- with the true ball in the robot frame and what the vision made of it
local frame_dir = os.getenv('FRAME_DIR') or ''
local frame_every = tonumber(os.getenv('FRAME_EVERY') or '') or 5
local next_frame = 0
local function dump_frame()
  if frame_dir == '' or Body.get_time() - t0 < next_frame then return end
  next_frame = next_frame + frame_every
  local draw = require('Tests.vision.draw')
  local cam = shm.open('camera.image')
  local w, h = cam.width[0], cam.height[0]
  local rgb = ffi.new('uint8_t[?]', w * h * 3)
  for i = 0, w * h - 1 do
    local pair = bit.band(i, bit.bnot(1)) * 2
    local y, u, v = cam.yuyv[2 * i], cam.yuyv[pair + 1] - 128, cam.yuyv[pair + 3] - 128
    rgb[3 * i] = math.max(0, math.min(255, y + 1.402 * v))
    rgb[3 * i + 1] = math.max(0, math.min(255, y - 0.344 * u - 0.714 * v))
    rgb[3 * i + 2] = math.max(0, math.min(255, y + 1.772 * u))
  end
  local seen = vision.ball_detected[0] ~= 0
  if seen then
    local bu, bv = vision.ball_image[0], vision.ball_image[1]
    for r = vision.ball_radius[0] + 1, vision.ball_radius[0] + 3 do
      local n = math.max(64, math.floor(8 * r))
      for k = 0, n - 1 do
        local px = math.floor(bu + r * math.cos(2 * math.pi * k / n))
        local py = math.floor(bv + r * math.sin(2 * math.pi * k / n))
        if px >= 0 and py >= 0 and px < w and py < h then
          rgb[3 * (py * w + px)], rgb[3 * (py * w + px) + 1], rgb[3 * (py * w + px) + 2] = 255, 0, 0
        end
      end
    end
  end
  local t = Body.get_time() - t0
  draw.write_png(string.format('%s/frame_%05.1f.png', frame_dir, t), rgb, w, h)
  local T = Sim.truth()
  local dx, dy = T.ball.x - T.x, T.ball.y - T.y
  local c, sn = math.cos(T.yaw), math.sin(T.yaw)
  local f = assert(io.open(frame_dir .. '/frames.txt', 'a'))
  f:write(string.format('t=%.1f ball_true=(%.2f,%.2f) seen=%d ball_seen=(%.2f,%.2f) head=(%.2f,%.2f)\n', t,
    c * dx + sn * dy, -sn * dx + c * dy, seen and 1 or 0, vision.ball_position[0], vision.ball_position[1],
    cam.head[0], cam.head[1]))
  f:close()
end
while Body.get_time() - t0 < limit do
  wait_quarter()
  log_step()
  dump_frame()
  local plus, minus = Sim.score()
  if plus > plus0 then goal = true break end
  if minus > minus0 then own = true break end
  if kill_at and not killed and Body.get_time() - t0 >= kill_at then
    killed = true
    local pid = vision_pid()
    print(string.format('killing vision (pid %s) at t=%.2f', tostring(pid), Body.get_time() - t0))
    io.stdout:flush()
    if pid then ffi.C.kill(pid, 9) end
  end
end
local T = Sim.truth()
print(string.format('result seed=%d goal=%d time=%.2f own=%d robot=(%.2f,%.2f) ball=(%.2f,%.2f) fallen=%s',
  seed, goal and 1 or 0, Body.get_time() - t0, own and 1 or 0, T.x, T.y, T.ball.x, T.ball.y, tostring(T.fallen)))
if trace then trace:close() end
if cap then cap:close() end
