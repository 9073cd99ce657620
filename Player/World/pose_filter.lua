-- The robot's pose on the field (x, y, yaw; origin at the centre, x towards the opponent goal): a
-- particle filter moved by odometry and weighted by goal-post sightings. The two goals look alike,
-- so a post sighting is matched to the nearest of the four real posts for each particle; the prior
-- (the robot starts in its own half) and the field's bounds break the symmetry.
--
-- The side: a pose and its mirror across the field (-x, -y, heading + pi) see the same posts. As
-- real teams do, the robot knows its side from the game: it is placed in its own half (the prior)
-- and stays there until the kick-off (`own_half`: from a placement until the game is PLAYING; the
-- world model's caller clears it), or it was placed at a known pose (set_pose); later, the reachable
-- region around the placement (by the distance walked) says where it cannot be yet. Once the belief
-- is confident where its mirror cannot be (or the pose was given), its heading
-- becomes the side's reference `side_a`, held as an offset from the IMU's yaw (Filter:imu; it
-- turns with the body, through falls too) or, without an IMU, turned by the odometry's turns. A
-- hypothesis whose heading is more than
-- `side_tolerance` from it is the mirror: never sampled, re-seeded or kept (weighted as an outlier).
local M = {}

local sqrt, cos, sin, atan2, exp, floor = math.sqrt, math.cos, math.sin, math.atan2, math.exp, math.floor
local pi = math.pi

local function wrap(a)
  a = a % (2 * pi)
  if a > pi then a = a - 2 * pi end
  return a
end
M.wrap = wrap

local Filter = {}
Filter.__index = Filter

-- field: { length, width, goal_width }; cfg: particles, odometry noise, post noise, prior
-- rng: a function returning uniform [0, 1) (seeded by the caller for reproducible runs)
function M.new(field, cfg, rng)
  local f = setmetatable({ field = field, cfg = cfg, rng = rng or math.random }, Filter)
  local hx, hw = field.length / 2, field.goal_width / 2
  f.posts = { { hx, hw }, { hx, -hw }, { -hx, hw }, { -hx, -hw } }
  f.n = cfg.particles
  f.px, f.py, f.pa, f.w = {}, {}, {}, {}
  f:init_prior()
  return f
end

function Filter:gauss()
  local u1, u2 = math.max(1e-12, self.rng()), self.rng()
  return sqrt(-2 * math.log(u1)) * cos(2 * pi * u2)
end

-- Uniform over the prior region (own half by default), any heading.
-- With the side known, the heading within side_tolerance of it.
function Filter:sample_prior(i)
  local r = self.cfg.prior -- { xmin, xmax, ymin, ymax }
  self.px[i] = r[1] + (r[2] - r[1]) * self.rng()
  self.py[i] = r[3] + (r[4] - r[3]) * self.rng()
  if self.side_a then
    self.pa[i] = wrap(self.side_a + self.cfg.side_tolerance * (2 * self.rng() - 1))
  else
    self.pa[i] = wrap(2 * pi * self.rng())
  end
end

-- Whether heading a is the mirror hypothesis's (the side is known and a is off it).
function Filter:mirrored(a)
  return self.side_a ~= nil and math.abs(wrap(a - self.side_a)) > self.cfg.side_tolerance
end

-- lines (optional): the touch lines the robot was placed on, facing into the field (y signs, e.g.
-- { -1 }: y = -width/2, heading +pi/2); without: anywhere in the own half, any heading. Placed on
-- one known line, the heading, and so the side, is known at once.
function Filter:init_prior(lines)
  self.side_a, self.side_offset = nil, nil -- placed anew: the side comes from the placement again
  self.own_half = true
  for i = 1, self.n do
    if lines then
      local s = lines[1 + floor(self.rng() * #lines)] or lines[1]
      local r = self.cfg.prior
      self.px[i] = r[1] + (r[2] - r[1]) * self.rng()
      self.py[i] = s * self.field.width / 2 + 0.1 * self:gauss()
      self.pa[i] = wrap(-s * pi / 2 + 0.15 * self:gauss())
    else
      self:sample_prior(i)
    end
    self.w[i] = 1 / self.n
  end
  self.walked = 0
  if lines and #lines == 1 then self:take_side(-lines[1] * pi / 2) end
  self:estimate()
end

-- Whether (x, y) can be reached from the prior region by the distance walked since (with the
-- odometry's error): right after placement the robot is in its own half, so a mirror pose across
-- the field (the goals look alike) cannot be it, however well it explains a sighting.
function Filter:reachable(x, y)
  local r, d = self.cfg.prior, self.walked * (1 + 2 * self.cfg.odom_trans_noise) + 0.3
  if self.own_half and x > self.cfg.own_half_margin then return false end
  return x >= r[1] - d and x <= r[2] + d and y >= r[3] - d and y <= r[4] + d
end

-- Puts every particle near a known pose (e.g. placed by the referee).
function Filter:set_pose(x, y, a, spread)
  spread = spread or 0.05
  for i = 1, self.n do
    self.px[i] = x + spread * self:gauss()
    self.py[i] = y + spread * self:gauss()
    self.pa[i] = wrap(a + spread * self:gauss())
    self.w[i] = 1 / self.n
  end
  self.walked = math.huge -- known: no constraint from the prior
  self:take_side(a)       -- ... and the side is this pose's
  self.own_half = false
  self:estimate()
end

-- Odometry: the robot moved (dx, dy) and turned da in its previous frame.
function Filter:move(dx, dy, da)
  local c = self.cfg
  local dist = sqrt(dx * dx + dy * dy)
  local st = c.odom_trans_noise * dist + 1e-4
  local sa = c.odom_rot_noise * math.abs(da) + c.odom_rot_per_m * dist + 1e-4
  local hl, hw = self.field.length / 2 + c.margin, self.field.width / 2 + c.margin
  self.walked = self.walked + dist
  if self.side_a and not self.side_offset then self.side_a = wrap(self.side_a + da) end
  -- the reachable part of the field (see Filter:reachable): its bounds clamp like the field's
  local r, d = c.prior, self.walked * (1 + 2 * c.odom_trans_noise) + 0.3
  local xlo, xhi = math.max(-hl, r[1] - d), math.min(hl, r[2] + d)
  if self.own_half then xhi = math.min(xhi, c.own_half_margin) end
  local ylo, yhi = math.max(-hw, r[3] - d), math.min(hw, r[4] + d)
  for i = 1, self.n do
    local a = self.pa[i]
    local ndx = dx + st * self:gauss()
    local ndy = dy + st * self:gauss()
    local ca, sa_ = cos(a), sin(a)
    local x = self.px[i] + ca * ndx - sa_ * ndy
    local y = self.py[i] + sa_ * ndx + ca * ndy
    -- the robot never leaves the field by much
    if x > xhi then x = xhi elseif x < xlo then x = xlo end
    if y > yhi then y = yhi elseif y < ylo then y = ylo end
    self.px[i], self.py[i] = x, y
    self.pa[i] = wrap(a + da + sa * self:gauss())
  end
end

-- Likelihood of seeing a post at range r, bearing b (robot frame) from particle i.
function Filter:post_likelihood(i, r, b)
  local c = self.cfg
  local x, y, a = self.px[i], self.py[i], self.pa[i]
  local best = 0
  local sr = c.post_range_noise * math.max(0.5, r)
  local sb = c.post_bearing_noise
  for k = 1, 4 do
    local p = self.posts[k]
    local ddx, ddy = p[1] - x, p[2] - y
    local er = sqrt(ddx * ddx + ddy * ddy) - r
    local eb = wrap(atan2(ddy, ddx) - a - b)
    local l = exp(-0.5 * (er * er / (sr * sr) + eb * eb / (sb * sb)))
    if l > best then best = l end
  end
  return best
end

-- Poses from which two posts seen at o1, o2 (robot frame) are the posts of one goal: one per goal
-- (the post order that puts the robot behind a goal is dropped). Sensor resetting uses them.
function Filter:poses_from_two_posts(o1, o2)
  local out = {}
  local hl, hw = self.field.length / 2 + self.cfg.margin, self.field.width / 2 + self.cfg.margin
  local P = self.posts
  for _, pair in ipairs({ { P[1], P[2] }, { P[2], P[1] }, { P[3], P[4] }, { P[4], P[3] } }) do
    local f1, f2 = pair[1], pair[2]
    local a = wrap(atan2(f2[2] - f1[2], f2[1] - f1[1]) - atan2(o2[2] - o1[2], o2[1] - o1[1]))
    local c, s = cos(a), sin(a)
    local x = f1[1] - (c * o1[1] - s * o1[2])
    local y = f1[2] - (s * o1[1] + c * o1[2])
    if x > -hl and x < hl and y > -hw and y < hw and math.abs(x) < self.field.length / 2
      and self:reachable(x, y) and not self:mirrored(a) then
      out[#out + 1] = { x, y, a }
    end
  end
  return out
end

-- Sensor resetting for one post seen at o (robot frame): k particles drawn from the belief (by
-- weight) are moved, keeping their heading, to where the sighting puts them given the real post
-- that heading matches best. The heading comes from the belief (the IMU keeps it well), the
-- position from the sighting: a belief that drifted is pulled back along the post's ray, and the
-- new particles stay near the belief's own hypotheses (at most project_max_jump from the particle
-- they came from: never the mirror pose across the field).
function Filter:project(o, k)
  if k <= 0 then return end
  local n = self.n
  local r0, b0 = sqrt(o[1] * o[1] + o[2] * o[2]), atan2(o[2], o[1])
  local hl, hw = self.field.length / 2 + self.cfg.margin, self.field.width / 2 + self.cfg.margin
  local cum, acc = self.cum or {}, 0
  self.cum = cum
  for i = 1, n do acc = acc + self.w[i] cum[i] = acc end
  local sr = self.cfg.post_range_noise * 0.5
  local nx, ny, na = {}, {}, {}
  local jump2 = self.cfg.project_max_jump ^ 2
  for _ = 1, k do
    -- a particle by weight (binary search of the cumulative weights)
    local u, lo, hi = self.rng() * acc, 1, n
    while lo < hi do
      local mid = floor((lo + hi) / 2)
      if cum[mid] < u then lo = mid + 1 else hi = mid end
    end
    local a = wrap(self.pa[lo] + 0.03 * self:gauss())
    -- the post this particle would see nearest to the sighting's bearing and range
    local best, bx, by = math.huge, 0, 0
    local x, y = self.px[lo], self.py[lo]
    for q = 1, 4 do
      local p = self.posts[q]
      local ddx, ddy = p[1] - x, p[2] - y
      local er = (sqrt(ddx * ddx + ddy * ddy) - r0) / (0.15 * math.max(0.5, r0))
      local eb = wrap(atan2(ddy, ddx) - a - b0) / 0.12
      local e = er * er + eb * eb
      if e < best then best, bx, by = e, p[1], p[2] end
    end
    local r = r0 * (1 + sr * self:gauss())
    local cx, cy = bx - r * cos(a + b0), by - r * sin(a + b0)
    -- only a jump the belief can stand behind: near the particle it came from
    if (cx - x) ^ 2 + (cy - y) ^ 2 < jump2 then nx[#nx + 1], ny[#ny + 1], na[#na + 1] = cx, cy, a end
  end
  for m = 1, #nx do
    if nx[m] > -hl and nx[m] < hl and ny[m] > -hw and ny[m] < hw and self:reachable(nx[m], ny[m])
      and not self:mirrored(na[m]) then
      local i = 1 + floor(self.rng() * n)
      if i > n then i = n end
      self.px[i], self.py[i], self.pa[i] = nx[m], ny[m], na[m]
    end
  end
end

-- Goal posts seen: list of {x, y} in the robot frame.
function Filter:observe_posts(posts)
  if #posts == 0 then return end
  -- how well the belief explains this sighting (the mean likelihood over the particles)
  local fit = 0
  for i = 1, self.n do
    local l = 1
    for _, p in ipairs(posts) do
      l = l * self:post_likelihood(i, sqrt(p[1] * p[1] + p[2] * p[2]), atan2(p[2], p[1]))
    end
    fit = fit + self.w[i] * l
  end
  self.fit = 0.8 * (self.fit or 1) + 0.2 * math.min(1, fit / 0.3)
  -- gate: a sighting a confident belief cannot explain at all is taken for a false post (only
  -- the running fit remembers it, so that sightings that keep contradicting end in a re-seed)
  if (self.confidence or 0) > self.cfg.gate_confidence and fit < self.cfg.gate_fit and self.fit >= 0.3 then
    self.gated = (self.gated or 0) + 1
    return
  end
  -- one badly explained sighting is more likely a false post than a wrong belief: re-seed only
  -- when the belief is weak or sightings have kept contradicting it (the running fit is low)
  local contradicted = self.fit < 0.3
  if #posts == 2 and ((self.confidence or 0) < self.cfg.reset_below or contradicted) then
    -- sensor resetting: a few particles jump to the poses this sighting implies
    local cands = self:poses_from_two_posts(posts[1], posts[2])
    -- each candidate in proportion to how well the current belief supports it (the history
    -- decides between the two mirror poses)
    local support, total_support = {}, 0
    for ci, c in ipairs(cands) do
      local sum = 1e-6
      for i = 1, self.n do
        local ddx, ddy, dda = self.px[i] - c[1], self.py[i] - c[2], wrap(self.pa[i] - c[3])
        sum = sum + self.w[i] * exp(-(ddx * ddx + ddy * ddy) / 0.5 - dda * dda / 0.5)
      end
      support[ci] = sum
      total_support = total_support + sum
    end
    if #cands > 0 then
      local k = floor(self.n * (contradicted and 0.3 or self.cfg.reset_fraction))
      for _ = 1, k do
        local u, ci = self.rng() * total_support, 1
        while ci < #cands and u > support[ci] do u = u - support[ci] ci = ci + 1 end
        local c = cands[ci]
        local i = 1 + floor(self.rng() * self.n)
        if i > self.n then i = self.n end
        local r = sqrt(posts[1][1] ^ 2 + posts[1][2] ^ 2)
        self.px[i] = c[1] + 0.05 * r * self:gauss()
        self.py[i] = c[2] + 0.05 * r * self:gauss()
        self.pa[i] = wrap(c[3] + 0.05 * self:gauss())
      end
    end
  end
  if #posts == 1 then
    local c = self.cfg
    local frac = contradicted and c.project_lost or
      ((self.confidence or 0) < c.reset_below and c.project_lost or c.project_fraction)
    self:project(posts[1], floor(self.n * frac))
  end
  local total = 0
  local floor_l = self.cfg.outlier -- a sighting may be false: never weight a particle to zero
  for i = 1, self.n do
    local l = 1
    for _, p in ipairs(posts) do
      local r = sqrt(p[1] * p[1] + p[2] * p[2])
      local b = atan2(p[2], p[1])
      l = l * (floor_l + (1 - floor_l) * self:post_likelihood(i, r, b))
    end
    -- two posts of one goal: their separation must fit a goal's width
    if #posts == 2 then
      local ddx, ddy = posts[1][1] - posts[2][1], posts[1][2] - posts[2][2]
      local sep = sqrt(ddx * ddx + ddy * ddy)
      local e = sep - self.field.goal_width
      l = l * (floor_l + exp(-0.5 * e * e / 0.3 ^ 2))
    end
    -- the mirror hypothesis explains a sighting as well as the truth: the side rules it out
    if self:mirrored(self.pa[i]) then l = l * floor_l * floor_l end
    self.w[i] = self.w[i] * l
    total = total + self.w[i]
  end
  self.last_likelihood = total
  if total <= 1e-300 then
    for i = 1, self.n do self.w[i] = 1 / self.n end
  else
    for i = 1, self.n do self.w[i] = self.w[i] / total end
  end
  self:resample_if_needed()
end

function Filter:resample_if_needed()
  local s2 = 0
  for i = 1, self.n do s2 = s2 + self.w[i] * self.w[i] end
  local neff = 1 / s2
  if neff > self.n * 0.5 then return end
  -- low-variance resampling
  local n = self.n
  local nx, ny, na = {}, {}, {}
  local step = 1 / n
  local u = self.rng() * step
  local c, k = self.w[1], 1
  for i = 1, n do
    while u > c and k < n do k = k + 1 c = c + self.w[k] end
    nx[i], ny[i], na[i] = self.px[k], self.py[k], self.pa[k]
    u = u + step
  end
  -- roughening: copies of one particle spread out a little, so the cloud can still move
  local rp, ra = self.cfg.roughen_position, self.cfg.roughen_angle
  for i = 1, n do
    nx[i] = nx[i] + rp * self:gauss()
    ny[i] = ny[i] + rp * self:gauss()
    na[i] = wrap(na[i] + ra * self:gauss())
  end
  self.px, self.py, self.pa = nx, ny, na
  for i = 1, n do self.w[i] = 1 / n end
  -- a few fresh particles keep the filter able to recover from a wrong lock
  local inject = floor(n * self.cfg.inject_fraction)
  for _ = 1, inject do
    local i = 1 + floor(self.rng() * n)
    if i > n then i = n end
    self:sample_prior(i)
  end
end

-- The pose: the weighted mean of the heaviest cluster of particles (a mean over two mirror or
-- otherwise distinct hypotheses would be a pose that is neither); a confidence in [0, 1].
local CELL, NBIN = 0.5, 12 -- m, heading bins of the histogram that finds the cluster
local hist, bx_, by_, ba_ = {}, {}, {}, {}
function Filter:estimate()
  local n, px, py, pa, w = self.n, self.px, self.py, self.pa, self.w
  for k in pairs(hist) do hist[k] = nil end
  for i = 1, n do
    local ix, iy = floor(px[i] / CELL), floor(py[i] / CELL)
    local ia = floor((pa[i] + pi) / (2 * pi) * NBIN) % NBIN
    bx_[i], by_[i], ba_[i] = ix, iy, ia
    local key = (ix * 64 + iy) * 16 + ia
    hist[key] = (hist[key] or 0) + w[i]
  end
  -- the bin whose neighbourhood (3 x 3 cells, 3 headings) holds the most weight
  local best, bi = -1, 1
  for i = 1, n do
    local sum = 0
    for dx = -1, 1 do
      for dy = -1, 1 do
        for da = -1, 1 do
          local key = ((bx_[i] + dx) * 64 + by_[i] + dy) * 16 + (ba_[i] + da) % NBIN
          sum = sum + (hist[key] or 0)
        end
      end
    end
    if sum > best then best, bi = sum, i end
  end
  -- its weighted mean, then the mean of the particles within 1 m and 0.6 rad of that
  local x0, y0, a0 = px[bi], py[bi], pa[bi]
  local x, y, a
  for pass = 1, 2 do
    local rx, ra = pass == 1 and 1.5 * CELL or 1.0, pass == 1 and 1.5 * 2 * pi / NBIN or 0.6
    local sx, sy, sc, ss, sw = 0, 0, 0, 0, 0
    for i = 1, n do
      if math.abs(px[i] - x0) <= rx and math.abs(py[i] - y0) <= rx and math.abs(wrap(pa[i] - a0)) <= ra then
        local wi = w[i]
        sx, sy, sw = sx + wi * px[i], sy + wi * py[i], sw + wi
        sc, ss = sc + wi * cos(pa[i]), ss + wi * sin(pa[i])
      end
    end
    if sw <= 0 then break end
    x, y, a = sx / sw, sy / sw, atan2(ss, sc)
    x0, y0, a0 = x, y, a
  end
  if not x then x, y, a = px[bi], py[bi], pa[bi] end
  self.x, self.y, self.a = x, y, a
  -- confidence: the whole cloud's spread (two hypotheses far apart make it low, whichever is
  -- reported), times how well it has explained recent sightings
  local sx, sy, sc, ss, sw = 0, 0, 0, 0, 0
  for i = 1, n do
    local wi = w[i]
    sx, sy, sw = sx + wi * px[i], sy + wi * py[i], sw + wi
    sc, ss = sc + wi * cos(pa[i]), ss + wi * sin(pa[i])
  end
  local mx, my, var = sx / sw, sy / sw, 0
  for i = 1, n do
    local ddx, ddy = px[i] - mx, py[i] - my
    var = var + w[i] * (ddx * ddx + ddy * ddy)
  end
  var = var / sw
  local rlen = sqrt(sc * sc + ss * ss) / sw -- 1 when all headings agree
  self.confidence = math.max(0, math.min(1, rlen * exp(-var / 0.5) * (self.fit or 1)))
  self:update_side()
  return x, y, a, self.confidence
end

-- The IMU's yaw (rad, any zero): the side's reference keeps its offset from it.
function Filter:imu(yaw)
  self.imu_yaw = yaw
  if self.side_offset then self.side_a = wrap(yaw + self.side_offset)
  elseif self.side_a then self.side_offset = wrap(self.side_a - yaw) end -- taken before the first reading
end

-- The side's reference is heading a (field frame) from now on.
function Filter:take_side(a)
  self.side_a = a
  self.side_offset = self.imu_yaw and wrap(a - self.imu_yaw) or nil
end

-- The side's reference from a confident belief, taken when the belief's mirror cannot be (in the
-- other half while the robot is known to be in its own, or out of reach of the placement).
function Filter:update_side()
  if self.side_a or self.confidence < self.cfg.side_confidence then return end
  if not self:reachable(-self.x, -self.y) then self:take_side(self.a) end
end

return M
