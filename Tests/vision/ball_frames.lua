-- Ball detection over seeded frames the sim renders (build/bin/sim_ball_frames; written by
-- ball_frames_test.sh with seeds no training run uses), through the vision pipeline with the camera
-- pose the renderer used. Prints recall, false detections, range and bearing errors, and TAP lines
-- for the goals named in GATE.
--   luajit Tests/vision/ball_frames.lua FRAMES KIND [GATE]     KIND: white | orange
-- GATE: comma-separated goals to fail on (recall, false, range, bearing, robots); the others only print.
-- DRAW=DIR writes a PNG per frame listed in DRAW_FRAMES (or each miss and false detection) with the
-- field boundary, the candidates and the detection drawn; with ROBOT_MISSES=1 also each frame where a
-- robot in view up to 3 m was missed or a robot detected with its feet in view near none (each printed).
local Config = require('Config')
local pipeline = require('Vision.pipeline')
local frames = require('Tools.ball_train.frames')
local draw = require('Tests.vision.draw')

local path, kind, gate = arg[1], arg[2], arg[3] or ''
assert(path and (kind == 'white' or kind == 'orange'), 'usage: ball_frames.lua FRAMES white|orange [GATE]')
local vcfg, ccfg = Config.load('vision'), Config.load('camera')
vcfg.ball.kind = kind
-- BALL_MODEL=FILE: another classifier than the config's (a model being trained)
if os.getenv('BALL_MODEL') then vcfg.ball.white.model = os.getenv('BALL_MODEL') end
local vp = assert(pipeline.new(vcfg, ccfg, nil))
local file = assert(frames.open(path))
local draw_dir = os.getenv('DRAW')

local st = { inview = 0, found = 0, wrong = 0, empty = 0, false_pos = 0, ranges = {}, bearings = {},
             worst = { err = -1, frame = -1 } }   -- the frame of the largest range error (DRAW_FRAMES)
local misses = {}
local robot_misses = os.getenv('ROBOT_MISSES') == '1'
local rs = { seen = 0, found = 0, errs = {}, dets = 0, false_pos = 0, team_ok = 0, team_named = 0,
             seen_all = 0, found_all = 0, errs_all = {}, cut = 0, cut_false = 0, behind = 0 }
local function bearing_gap(a, b)
  local d = math.abs(a - b) % (2 * math.pi)
  return d > math.pi and 2 * math.pi - d or d
end
-- The part of robot r's width (0.24 m, as bearings) that robots nearer than it hide: the sim's
-- truth knows where a robot stands, not whether another one stands in front of it.
local function hidden(r, all)
  local rr = math.sqrt(r.x * r.x + r.y * r.y)
  local hr, br = math.atan(0.12 / rr), math.atan2(r.y, r.x)
  local cover = 0
  for _, q in ipairs(all) do
    local rq = math.sqrt(q.x * q.x + q.y * q.y)
    if q ~= r and rq < rr - 0.1 then
      local hq, d = math.atan(0.12 / rq), bearing_gap(math.atan2(q.y, q.x), br)
      cover = cover + math.max(0, math.min(hr, d + hq) - math.max(-hr, d - hq))
    end
  end
  return math.min(1, cover / (2 * hr))
end
for fr in file:each() do
  assert(math.abs(fr.cm.f - vp.cm.f) < 1e-6, 'the renderer and the vision disagree on the focal length')
  local det = vp:detect(fr, fr.pose)
  local b, ball = fr.ball, det.ball
  local inview = b.visible >= 0.95 and b.distance >= 0.3 and b.distance <= 4
  local note, rmiss
  if inview then
    st.inview = st.inview + 1
    local tx, ty = b.distance * math.cos(b.bearing), b.distance * math.sin(b.bearing)
    if ball.detected and math.sqrt((ball.x - tx) ^ 2 + (ball.y - ty) ^ 2) <= math.max(0.25, 0.25 * b.distance) then
      st.found = st.found + 1
      local r = math.sqrt(ball.x ^ 2 + ball.y ^ 2)
      if b.distance <= 3 then
        local err = math.abs(r - b.distance) / b.distance
        st.ranges[#st.ranges + 1] = err
        if err > st.worst.err then st.worst.err, st.worst.frame = err, fr.index end
      end
      local e = math.abs(math.atan2(ball.y, ball.x) - b.bearing)
      if e > math.pi then e = 2 * math.pi - e end
      st.bearings[#st.bearings + 1] = math.deg(e)
    else
      if ball.detected then st.wrong = st.wrong + 1 end
      note = ball.detected and 'wrong place' or 'missed'
    end
  elseif b.visible == 0 then
    st.empty = st.empty + 1
    if ball.detected then
      st.false_pos = st.false_pos + 1
      note = 'false'
    end
  end
  -- robots whose middle on the ground is in the image with half a robot's width (0.12 m) to spare
  -- on either side, 0.3 .. 3 m away (and, apart, at any range the scenes have: up to 4 m): found
  -- when a detection lies within 0.5 m; a detection with its feet in view near no robot (within
  -- 0.7 m) is a false one; one with its feet below the image only bounds the range (the feet are
  -- nearer), so it is a false one when no robot stands in its bearing at most 0.5 m beyond it
  local robots = det.robots
  for _, r in ipairs(fr.robots) do
    local range = math.sqrt(r.x * r.x + r.y * r.y)
    local half = fr.cm.f * 0.12 / math.max(range, 0.1)
    local shown = r.visible > 0 and range >= 0.3 and r.u >= half and r.u <= fr.width - half
    -- a robot more than half hidden behind nearer ones is not in view (counted apart)
    if shown and hidden(r, fr.robots) > 0.5 then
      shown = false
      if range <= 3 then rs.behind = rs.behind + 1 end
    end
    if shown then
      local near3 = range <= 3
      rs.seen_all = rs.seen_all + 1
      if near3 then rs.seen = rs.seen + 1 end
      local best, bi
      for i = 1, robots.n do
        local e = math.sqrt((robots[i].x - r.x) ^ 2 + (robots[i].y - r.y) ^ 2)
        if e <= 0.5 and (not best or e < best) then best, bi = e, i end
      end
      if best then
        rs.found_all = rs.found_all + 1
        rs.errs_all[#rs.errs_all + 1] = best
      end
      if not best and near3 and robot_misses then
        print(string.format('robot missed: frame %d, %.2f m %+.1f deg, u %.0f v %.0f, hidden %.2f', fr.index, range,
                            math.deg(math.atan2(r.y, r.x)), r.u, r.v, hidden(r, fr.robots)))
        rmiss = true
      end
      if best and near3 then
        rs.found = rs.found + 1
        rs.errs[#rs.errs + 1] = best
        -- the sim's team 1 wears red (vision's 1), team 2 blue (vision's 0)
        if robots[bi].team >= 0 then
          rs.team_named = rs.team_named + 1
          if robots[bi].team == (r.team == 1 and 1 or 0) then rs.team_ok = rs.team_ok + 1 end
        end
      end
    end
  end
  for i = 1, robots.n do
    local d = robots[i]
    local near = false
    if d.foot_visible then
      rs.dets = rs.dets + 1
      for _, r in ipairs(fr.robots) do
        if math.sqrt((d.x - r.x) ^ 2 + (d.y - r.y) ^ 2) <= 0.7 then near = true end
      end
      if not near then
        rs.false_pos = rs.false_pos + 1
        if robot_misses then
          print(string.format('robot false: frame %d, %.2f m %+.1f deg, box u %d-%d v %d-%d', fr.index, d.range,
                              math.deg(math.atan2(d.y, d.x)), d.u0, d.u1, d.v0, d.v1))
          rmiss = true
        end
      end
    else
      rs.cut = rs.cut + 1
      -- the box's half width as an angle, and 0.1 rad
      local tol = 0.5 * (d.u1 - d.u0) / fr.cm.f + 0.1
      for _, r in ipairs(fr.robots) do
        if bearing_gap(math.atan2(d.y, d.x), math.atan2(r.y, r.x)) <= tol and
           math.sqrt(r.x * r.x + r.y * r.y) <= d.range + 0.5 then near = true end
      end
      if not near then rs.cut_false = rs.cut_false + 1 end
    end
  end
  if note then misses[#misses + 1] = string.format('frame %d: ball %.2f m %+.1f deg visible %.2f: %s', fr.index,
                                                   b.distance, math.deg(b.bearing), b.visible, note) end
  if draw_dir and (note or rmiss or (os.getenv('DRAW_FRAMES') or ''):find(',' .. fr.index .. ',', 1, true)) then
    draw.frame(string.format('%s/%s_%04d.png', draw_dir, kind, fr.index), fr, vp, det, b)
  end
end

local function stats(list)
  table.sort(list)
  local n, sum = #list, 0
  for _, v in ipairs(list) do sum = sum + v end
  if n == 0 then return 0, 0, 0 end
  return sum / n, list[math.max(1, math.ceil(0.95 * n))], list[n]
end
for i = 1, math.min(#misses, 30) do print(misses[i]) end
local recall = st.found / math.max(1, st.inview)
local fp = st.false_pos / math.max(1, st.empty)
local rm, r95, rmax = stats(st.ranges)
local bm, b95, bmax = stats(st.bearings)
print(string.format('%s ball: recall %d/%d = %.1f%% (fully in view, 0.3-4 m; %d detected elsewhere), '
  .. 'false detections %d/%d frames without the ball = %.2f%%', kind, st.found, st.inview, 100 * recall, st.wrong,
  st.false_pos, st.empty, 100 * fp))
print(string.format('%s ball: range error (<= 3 m, %d) mean %.1f%% p95 %.1f%% max %.1f%% (frame %d); bearing error '
  .. 'mean %.2f p95 %.2f max %.2f deg', kind, #st.ranges, 100 * rm, 100 * r95, 100 * rmax, st.worst.frame, bm, b95,
  bmax))
local em, e95, emax = stats(rs.errs)
print(string.format('robots: recall %d/%d = %.1f%% (in view, 0.3-3 m, not cut by the image side, at most half '
  .. 'hidden behind nearer robots: %d more were); position error mean %.2f p95 %.2f max %.2f m', rs.found, rs.seen,
  100 * rs.found / math.max(1, rs.seen), rs.behind, em, e95, emax))
em, e95, emax = stats(rs.errs_all)
print(string.format('robots: recall %d/%d = %.1f%% (in view, 0.3 m and beyond: the scenes place them up to 4 m); '
  .. 'position error mean %.2f p95 %.2f max %.2f m', rs.found_all, rs.seen_all,
  100 * rs.found_all / math.max(1, rs.seen_all), em, e95, emax))
print(string.format('robots: detections with the feet in view near no robot %d/%d; with the feet below the image '
  .. '(a range bound) in no robot\'s bearing %d/%d', rs.false_pos, rs.dets, rs.cut_false, rs.cut))
print(string.format('robots: team colour named for %d of the %d found, right for %d', rs.team_named, rs.found,
  rs.team_ok))
local n = 0
local function tap(name, ok, text)
  if not gate:find(name, 1, true) then return end
  n = n + 1
  print((ok and 'ok ' or 'not ok ') .. n .. ' - ' .. kind .. ' ' .. text)
end
tap('recall', recall >= 0.95, string.format('recall %.1f%% >= 95%%', 100 * recall))
tap('false', fp <= 0.01, string.format('false detections %.2f%% <= 1%%', 100 * fp))
tap('range', rmax <= 0.10, string.format('range error max %.1f%% <= 10%% (up to 3 m)', 100 * rmax))
tap('bearing', bmax <= 3, string.format('bearing error max %.2f deg <= 3', bmax))
tap('robots', rs.found >= 0.9 * rs.seen,
    string.format('robot recall %.1f%% >= 90%%', 100 * rs.found / math.max(1, rs.seen)))
n = n + 1
print(string.format('%s %d - %s frames scored: %d with the ball in view, %d without', st.inview >= 20 and 'ok' or
  'not ok', n, kind, st.inview, st.empty))
print('1..' .. n)
