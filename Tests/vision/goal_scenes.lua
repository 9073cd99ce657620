-- Goal-post detection over seeded sim scenes (run by goal_scenes_test.sh with dcm_sim in
-- lockstep). Like sim_scenes.lua: this script is a lockstep participant that holds the robot in a
-- stance, places it (sim block requests), points the head, lets the world settle, takes a rendered
-- frame through the sim camera driver and the vision pipeline (Player/Vision), and compares the
-- goal posts found with the sim's truth (posts of both goals from Config/platforms/Sim/sim.lua).
-- Two kinds of scene: a goal ahead (robot anywhere on the field facing roughly towards one of the
-- goals, head across the range that keeps the horizon in view), and no goal in view (every post
-- projects outside the image). Prints one line per scene and TAP results.
--   luajit Tests/vision/goal_scenes.lua [NSCENES] [SEED]
local Config = require('Config')
local project = require('Vision.project')

local NSCENES = tonumber(arg[1]) or 90
local SEED = tonumber(arg[2]) or 1

local scfg = Config.load('sim')
local world = require('Tests.vision.scene_lib').new()
local vp, cm = world.vp, world.cm
local sensor, sim, tick, request = world.sensor, world.sim, world.tick, world.request

-- the four posts' axes (field frame) and their size
local GX = scfg.field.length / 2
local DIA = scfg.goal.post_diameter
local HW = scfg.goal.width / 2 + DIA / 2
local POST_H = scfg.goal.height
local POSTS = { { GX, HW }, { GX, -HW }, { -GX, HW }, { -GX, -HW } }


math.randomseed(SEED)
local function rnd(a, b) return a + (b - a) * math.random() end
local function wrap(a) return (a + math.pi) % (2 * math.pi) - math.pi end

-- A post (robot frame px, py) is in view: its base and its axis up to 0.8 m (above the camera)
-- project inside the image with a margin of the post's width. Partly in view: any of its axis.
local function post_view(pose, px, py)
  local ub, vb, depth = project.to_image(cm, pose, px, py, 0)
  local um, vm = project.to_image(cm, pose, px, py, 0.8)
  local ut, vt = project.to_image(cm, pose, px, py, POST_H)
  if not ub or not um or not ut then return 'out' end
  local m = cm.f * DIA / depth + 4
  local W, H = cm.width, cm.height
  if ub > m and ub < W - m and um > m and um < W - m and vb < H - 4 and vm > 2 then return 'in' end
  local umin, umax = math.min(ub, ut) - m, math.max(ub, ut) + m
  if umax < 0 or umin > W or vb < 0 or vt > H then return 'out' end
  return 'partly'
end

local st = { posts_in = 0, found = 0, range_n = 0, goal_scenes = 0, empty = 0, empty_false = 0,
             dets = 0, unmatched = 0 }
local worst_range, sum_range, worst_bearing = 0, 0, 0

local scene = 0
while scene < NSCENES do
  scene = scene + 1
  local empty = scene % 3 == 0
  local rx, ry, ryaw, pan, tilt
  if empty then
    -- the middle of the field facing a touch line, head across its range: lines, the centre
    -- circle, the ball at the feet, but no goal (scored as empty only if no post projects into the image)
    rx, ry = rnd(-1.5, 1.5), rnd(-2.5, 2.5)
    ryaw = (math.random() < 0.5 and 1 or -1) * math.pi / 2 + rnd(-0.3, 0.3)
    pan, tilt = rnd(-0.5, 0.5), rnd(-0.9, 0.2)
  else
    -- on the field, facing one of the goals within +-0.5 rad, head pan within +-0.4
    rx, ry = rnd(-4, 3.5), rnd(-2.8, 2.8)
    local gx = (scene % 2 == 0) and GX or -GX
    if math.abs(gx - rx) < 1.2 then rx = rx - (gx > 0 and 1.5 or -1.5) end
    ryaw = math.atan2(-ry, gx - rx) + rnd(-0.5, 0.5)
    pan, tilt = rnd(-0.4, 0.4), rnd(-0.35, 0.15)
  end
  world.stance(pan, tilt)
  for _ = 1, 30 do tick() end                 -- head and legs reach the stance
  request(2, rx, ry, ryaw)
  -- the ball behind the robot, or in empty scenes at its feet (as when dribbling)
  local ball_d = empty and rnd(0.2, 0.6) or -3
  request(3, rx + ball_d * math.cos(ryaw + pan), ry + ball_d * math.sin(ryaw + pan), 0, 0)
  for _ = 1, 60 do tick() end                 -- settle ~0.5 s
  local t_x, t_y, t_yaw = sim.robot[0], sim.robot[1], sim.robot[3]
  local frame, q = world.frame()
  local det = assert(vp:process(frame, q, { sensor.angle[0], sensor.angle[1] }))
  local goals = det.goals
  local pose = vp.pose
  -- true posts in the robot frame and whether they are in view
  local c, s = math.cos(-t_yaw), math.sin(-t_yaw)
  local truth, nin, npartly = {}, 0, 0
  for k, P in ipairs(POSTS) do
    local dx, dy = P[1] - t_x, P[2] - t_y
    local tx, ty = c * dx - s * dy, s * dx + c * dy
    local view = post_view(pose, tx, ty)
    truth[k] = { x = tx, y = ty, view = view }
    if view == 'in' then nin = nin + 1 elseif view == 'partly' then npartly = npartly + 1 end
  end
  local line = string.format('scene %3d: robot %+.2f %+.2f %+4.0f deg head %+.2f %+.2f: ', scene, t_x, t_y,
    math.deg(t_yaw), pan, tilt)
  -- each detection matched to the nearest true post (within 0.5 m or 20% of its range)
  local matched = {}
  local parts = {}
  for i = 1, goals.n do
    local g = goals[i]
    local best, bd
    for k, T in ipairs(truth) do
      local d = math.sqrt((g.x - T.x) ^ 2 + (g.y - T.y) ^ 2)
      if not bd or d < bd then best, bd = k, d end
    end
    local T = truth[best]
    local tr = math.sqrt(T.x ^ 2 + T.y ^ 2)
    if bd <= math.max(0.5, 0.2 * tr) and T.view ~= 'out' then
      matched[best] = g
      parts[#parts + 1] = string.format('post at %.2f m %+.1f deg (true %.2f m %+.1f deg)',
        math.sqrt(g.x ^ 2 + g.y ^ 2), math.deg(math.atan2(g.y, g.x)), tr, math.deg(math.atan2(T.y, T.x)))
    else
      st.unmatched = st.unmatched + 1
      parts[#parts + 1] = string.format('FALSE post at %.2f, %.2f', g.x, g.y)
    end
  end
  st.dets = st.dets + goals.n
  if empty then
    if nin + npartly == 0 then
      st.empty = st.empty + 1
      if goals.n > 0 then st.empty_false = st.empty_false + 1 end
      line = line .. 'no goal in view: ' .. (goals.n == 0 and 'none (correct)' or table.concat(parts, ', '))
    else
      line = line .. 'a post in view (not scored as empty): ' .. table.concat(parts, ', ')
    end
  else
    st.goal_scenes = st.goal_scenes + 1
    for k, T in ipairs(truth) do
      if T.view == 'in' then
        st.posts_in = st.posts_in + 1
        local g = matched[k]
        if g then
          st.found = st.found + 1
          local tr, er = math.sqrt(T.x ^ 2 + T.y ^ 2), math.sqrt(g.x ^ 2 + g.y ^ 2)
          local re = math.abs(er - tr) / tr
          local be = math.abs(wrap(math.atan2(g.y, g.x) - math.atan2(T.y, T.x)))
          worst_range, worst_bearing = math.max(worst_range, re), math.max(worst_bearing, be)
          sum_range, st.range_n = sum_range + re, st.range_n + 1
        else
          local rj = require('Vision.detect').reject
          parts[#parts + 1] = string.format('MISSED post at %.2f m %+.1f deg (%s %.3g %.3g)',
            math.sqrt(T.x ^ 2 + T.y ^ 2), math.deg(math.atan2(T.y, T.x)), rj.why, rj.a, rj.b)
        end
      end
    end
    line = line .. string.format('%d post(s) in view, %d partly: ', nin, npartly) ..
      (#parts > 0 and table.concat(parts, ', ') or 'none')
  end
  print(line)
  if os.getenv('DUMP_POSTS') and (line:find('MISSED') or line:find('FALSE')) then
    os.execute(string.format('build/bin/lut_tool render --shm -o /tmp/posts_%d.png >/dev/null', scene))
  end
end
world.leave()

local recall = st.found / math.max(1, st.posts_in)
local false_rate = st.unmatched / math.max(1, st.dets)
print(string.format('posts: recall %d/%d = %.1f%%, range error mean %.1f%% max %.1f%%, bearing error max %.2f deg; '
  .. 'false posts %d of %d detections = %.1f%%; frames without a goal with a post reported %d/%d',
  st.found, st.posts_in, 100 * recall, 100 * sum_range / math.max(1, st.range_n), 100 * worst_range,
  math.deg(worst_bearing), st.unmatched, st.dets, 100 * false_rate, st.empty_false, st.empty))
local n = 0
local function tap(ok, name)
  n = n + 1
  print((ok and 'ok ' or 'not ok ') .. n .. ' - ' .. name)
end
tap(st.posts_in >= NSCENES / 2, 'enough posts fully in view: ' .. st.posts_in)
tap(st.empty >= NSCENES / 6, 'enough frames without a goal: ' .. st.empty)
tap(recall >= 0.90, string.format('post recall %.1f%% >= 90%%', 100 * recall))
tap(worst_range <= 0.10, string.format('post range error max %.1f%% <= 10%%', 100 * worst_range))
tap(worst_bearing <= math.rad(3), string.format('post bearing error max %.2f deg <= 3', math.deg(worst_bearing)))
tap(st.unmatched == 0, string.format('no false posts: %d of %d detections', st.unmatched, st.dets))
tap(st.empty_false == 0, string.format('no post in frames without a goal: %d/%d', st.empty_false, st.empty))
print('1..' .. n)
