-- DIAGNOSTIC: runs the world model (Player/World, Config/<platform>/behavior.lua's `world`) over
-- inputs recorded by Tools/tune/behavior_record.lua and compares its pose with the recorded
-- truth. Open loop (the robot's path is the recorded one), so it measures the localisation alone.
--   luajit Tools/tune/replay_world.lua RECORD... (after `source Run/env.sh`)
-- Per record: the share of playing time (from 3 s on) the pose is off by > 0.7 m or > 0.4 rad
-- ("bad"), the share it is that far off while claiming confidence >= 0.5 ("sure+bad"), the mean
-- position error, the share of time World:localised() holds and the share it holds while bad.
-- env: REPLAY_SEEDS=N: each record N times with different filter seeds (a particle filter's path
-- depends on its random numbers: one replay is one sample); REPLAY_QUIET=1: the total only;
-- REPLAY_TRACE=1: truth, estimate, confidence and posts seen, twice a second;
-- REPLAY_OVERRIDE="pose.key=value key=value ...": other `world` settings without editing the config.
local Config = require('Config')
local World = require('World.world')

local wrap = require('World.pose_filter').wrap
local cfg = Config.load('behavior')
for k, v in (os.getenv('REPLAY_OVERRIDE') or ''):gmatch('([%w_.]+)=(%S+)') do
  local t, key = cfg.world, k
  local sub, rest = k:match('^(%w+)%.(.+)$')
  if sub then t, key = cfg.world[sub], rest end
  rawset(t, key, tonumber(v) or (v == 'true' and true) or (v == 'false' and false) or v)
end
local quiet = (os.getenv('REPLAY_QUIET') or '') ~= ''
local tracing = (os.getenv('REPLAY_TRACE') or '') ~= ''

-- one record line as numbers; nil for a comment or a line cut off (the process stopped mid-write)
local function parse(line)
  local f = {}
  for v in line:gmatch('%S+') do f[#f + 1] = v end
  local np = tonumber(f[12] or '')
  if f[1] ~= 's' or not np or #f ~= 15 + 2 * np then return nil end
  local posts = {}
  for k = 1, np do posts[k] = { tonumber(f[11 + 2 * k]), tonumber(f[12 + 2 * k]) } end
  local i = 13 + 2 * np
  return {
    t = tonumber(f[2]), game = f[3], odom = { tonumber(f[4]), tonumber(f[5]), tonumber(f[6]) },
    imu = tonumber(f[7]), truth = { tonumber(f[i]), tonumber(f[i + 1]), tonumber(f[i + 2]) },
    vis = { frame = tonumber(f[8]), ball_detected = f[9] == '1', ball = { tonumber(f[10]), tonumber(f[11]) },
      posts = posts },
  }
end

-- replays one record with one filter seed; returns its counts
local function replay(path, seed, label)
  local w = World.new(setmetatable({ seed = seed }, { __index = cfg.world }))
  local c = { n = 0, bad = 0, surebad = 0, err = 0, loc = 0, locbad = 0 }
  local prev_game, t_play, next_trace, seen = nil, nil, 0, ''
  for line in io.lines(path) do
    local r = parse(line)
    if r then
      -- GameFSM's initial state resets the pose when the game leaves it
      if prev_game == 'initial' and r.game ~= 'initial' then w:reset_pose() end
      prev_game = r.game
      w:update(r.t, r.odom, r.vis, cfg.world.imu_yaw and r.imu or nil)
      local p, tr = w.pose, r.truth
      if #r.vis.posts > 0 then seen = seen .. string.format(' %.1f%s', r.t, #r.vis.posts == 2 and '*' or '') end
      if tracing and r.t >= next_trace then
        next_trace = r.t + 0.5
        io.write(string.format('%7.2f %-8s true %6.2f %6.2f %6.2f est %6.2f %6.2f %6.2f conf %.2f fit %.2f posts%s\n',
          r.t, r.game, tr[1], tr[2], tr[3], p.x, p.y, p.a, p.confidence, p.fit or -1, seen))
        seen = ''
      end
      if r.game == 'playing' then
        t_play = t_play or r.t
        if r.t - t_play > 3 then
          local e = math.sqrt((p.x - tr[1]) ^ 2 + (p.y - tr[2]) ^ 2)
          local bad = e > 0.7 or math.abs(wrap(p.a - tr[3])) > 0.4
          local loc = w:localised()
          c.n, c.err = c.n + 1, c.err + e
          if bad then c.bad = c.bad + 1 end
          if bad and p.confidence >= 0.5 then c.surebad = c.surebad + 1 end
          if loc then c.loc = c.loc + 1 end
          if loc and bad then c.locbad = c.locbad + 1 end
        end
      end
    end
  end
  if c.n > 0 and not quiet then
    print(string.format('%-28s steps=%5d bad=%.2f sure+bad=%.2f mean_err=%.2f m localised=%.2f loc+bad=%.2f',
      label, c.n, c.bad / c.n, c.surebad / c.n, c.err / c.n, c.loc / c.n, c.locbad / c.n))
  end
  return c
end

local nseeds = tonumber(os.getenv('REPLAY_SEEDS') or '') or 1
local tot = { n = 0, bad = 0, surebad = 0, loc = 0, locbad = 0 }
for _, path in ipairs(arg) do
  for rep = 1, nseeds do
    local seed = (tonumber(path:match('record_(%d+)')) or 1) + 1000 * (rep - 1)
    local c = replay(path, seed, (path:match('[^/]+/[^/]+$') or path) .. '#' .. rep)
    for k in pairs(tot) do tot[k] = tot[k] + c[k] end
  end
end
if tot.n > 0 then
  print(string.format('ALL steps=%d bad=%.3f sure+bad=%.3f localised=%.3f loc+bad=%.3f', tot.n, tot.bad / tot.n,
    tot.surebad / tot.n, tot.loc / tot.n, tot.locbad / tot.n))
end
