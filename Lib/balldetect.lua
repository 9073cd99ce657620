-- Field boundary, ball candidates and the ball classifier (Modules/balldetect, libhrpbd) from LuaJIT.
--
--   local balldetect = require('balldetect')
--   local bd = balldetect.new(320, 240)                  -- workspace for label images up to that size
--   bd:boundary(labels, wl, hl, 8, 4)                    -- bd.top[x]: first field row of label column x
--   bd:set_view(cm, pose)                                -- the camera at the frame (Vision.project's)
--   local n = bd:candidates(labels, wl, hl, 2, 8, 0.07, cfg)   -- bd.cand[0 .. n-1]: u, v, radius, score
--   local mlp = assert(balldetect.load_model('Config/common/ball_white.mlp'))
--   local p = bd:classify(mlp, yuyv, 640, 480, bd.cand[0])      -- probability 0..1 (also in cand.prob)
--   bd:settle(labels, wl, hl, 2, 8, 0.07, bd.cand[0])    -- the ball chosen: its centre settled
--   bd:fit(labels, wl, hl, 2, 8, 0.07, u0, v0, bd.cand[0])  -- then fitted to its outline (u0, v0: before settle)
--   local n = bd:obstacles(labels, wl, hl, cfg)          -- bd.obst[0 .. n-1]: x0, x1, top, foot, red, blue, fx0, fx1
-- Nothing on the per-frame path allocates.
local ffi = require('ffi')
local native = require('native')

native.cdef('balldetect')   -- Modules/balldetect/balldetect.h

local C = native.load('bd')

local NFEAT = 16 * 16 + 2 * 4 * 4 + 3   -- balldetect.h BD_NFEAT
local M = { C = C, NFEAT = NFEAT, MAXCAND = 16, MAXOBST = 24 }

local errbuf = ffi.new('char[512]')

-- Reads a classifier file (a path relative to the repo root, or absolute). nil, err naming the file.
function M.load_model(path)
  if type(path) ~= 'string' then error('balldetect.load_model: path must be a string', 2) end
  if path:sub(1, 1) ~= '/' then path = native.root() .. '/' .. path end
  local m = C.bd_mlp_load(path, errbuf, 512)
  if m == nil then return nil, ffi.string(errbuf) end
  return ffi.gc(m, C.bd_mlp_free)
end

local Bd = {}
Bd.__index = Bd

function M.new(max_w, max_h)
  local w = C.bd_new(max_w, max_h)
  if w == nil then error('balldetect.new: bad size or out of memory', 2) end
  return setmetatable({
    w = ffi.gc(w, C.bd_free), max_w = max_w,
    top = ffi.new('int16_t[?]', max_w),
    view = ffi.new('bd_view'),
    cand = ffi.new('bd_candidate[?]', M.MAXCAND),
    feat = ffi.new('float[?]', NFEAT),
    obst = ffi.new('bd_obstacle[?]', M.MAXOBST),
  }, Bd)
end

-- The field boundary of a label image into self.top; returns the number of columns with field.
function Bd:boundary(labels, wl, hl, green, min_run)
  return C.bd_field_boundary(self.w, labels, wl, hl, green, min_run, self.top)
end

-- The camera at the frame: cm = Vision.project.camera(...), pose from kinematics' camera_pose;
-- pose.blur (optional): { du, dv } px the image moved during the exposure.
function Bd:set_view(cm, pose)
  local v = self.view
  v.f, v.cx, v.cy, v.height = cm.f, cm.cx, cm.cy, pose.height
  for i = 0, 8 do v.R[i] = pose.R[i + 1] end
  local b = pose.blur
  v.blur[0], v.blur[1] = b and b[1] or 0, b and b[2] or 0
end

-- Ball candidates (after boundary and set_view) into self.cand[0 .. n-1]; returns n.
-- cfg: step (labels), min_inner, max_ring, min_radius (px), max_candidates.
function Bd:candidates(labels, wl, hl, scale, green, ball_r, cfg)
  local n = C.bd_candidates(self.w, labels, wl, hl, scale, green, self.top, self.view, ball_r, cfg.step,
                            cfg.min_inner, cfg.max_ring, cfg.min_radius, self.cand,
                            math.min(cfg.max_candidates, M.MAXCAND))
  if n < 0 then error('balldetect: bad arguments to bd_candidates', 2) end
  return n
end

-- The centre of the candidate chosen as the ball settled (bd_settle: more centroid passes).
function Bd:settle(labels, wl, hl, scale, green, ball_r, c)
  if C.bd_settle(labels, wl, hl, scale, green, self.top, self.view, ball_r, c) < 0 then
    error('balldetect: bad arguments to bd_settle', 2)
  end
end

-- The centre of the ball chosen from its outline (bd_fit), tried from its centre and from (u0, v0)
-- (before settle); returns the edge points on the fitted outline, 0 when it was left as it was.
function Bd:fit(labels, wl, hl, scale, green, ball_r, u0, v0, c)
  local n = C.bd_fit(labels, wl, hl, scale, green, self.top, self.view, ball_r, u0, v0, c)
  if n < 0 then error('balldetect: bad arguments to bd_fit', 2) end
  return n
end

-- The features of a candidate (into self.feat) at the model's margin.
function Bd:features(mlp, yuyv, width, height, u, v, radius)
  C.bd_features(yuyv, width, height, u, v, radius, C.bd_mlp_margin(mlp), self.feat)
  return self.feat
end

-- The classifier's probability that candidate c is a ball (also stored in c.prob).
function Bd:classify(mlp, yuyv, width, height, c)
  local f = self:features(mlp, yuyv, width, height, c.u, c.v, c.radius)
  c.prob = C.bd_mlp_eval(mlp, f)
  return c.prob
end

-- Obstacles standing on the field (after boundary) into self.obst[0 .. n-1]; returns n.
-- cfg: field (label bits of field and lines), red, blue (team colours' bits), min_run, min_below, max_gap,
-- leg_gap, min_width.
function Bd:obstacles(labels, wl, hl, cfg)
  local n = C.bd_obstacles(self.w, labels, wl, hl, self.top, cfg.field, cfg.red, cfg.blue, cfg.min_run,
                           cfg.min_below, cfg.max_gap, cfg.leg_gap, cfg.min_width, self.obst, M.MAXOBST)
  if n < 0 then error('balldetect: bad arguments to bd_obstacles', 2) end
  return n
end

return M
