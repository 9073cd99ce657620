-- Training samples for the white-ball classifier: runs the vision's own candidate search
-- (Modules/balldetect through Vision's config) over a sim_ball_frames file and writes each
-- candidate's features with its label, plus features at the true ball (jittered) as positives.
--   luajit Tools/ball_train/samples.lua FRAMES OUT [SEED]     (OUT is appended to)
-- OUT records: u8 label (1 ball, 0 not), then NFEAT float32. A candidate is a ball when its centre is
-- within half the ball's radius of the truth and at least half the ball shows; not a ball when it is
-- more than a radius away or the ball hardly shows (in between: left out, neither).
local ffi = require('ffi')
local Config = require('Config')
local imageproc = require('imageproc')
local balldetect = require('balldetect')
local pipeline = require('Vision.pipeline')
local frames = require('Tools.ball_train.frames')

local path, out_path, seed = arg[1], arg[2], tonumber(arg[3]) or 1
if not path or not out_path then
  io.stderr:write('usage: luajit Tools/ball_train/samples.lua FRAMES OUT [SEED]\n')
  os.exit(2)
end
local vcfg = Config.load('vision')
local w = vcfg.ball.white
local file = assert(frames.open(path))
local lut = assert(pipeline.load_lut(vcfg))
local p = imageproc.pipeline({ width = file.width, height = file.height, scale = vcfg.scale, block = vcfg.block,
                               lut = lut })
local bd = balldetect.new(p.wa, p.ha)
local out = assert(io.open(out_path, 'ab'))
local NF = balldetect.NFEAT
local feat = ffi.new('float[?]', NF)
local margin = tonumber(os.getenv('BALL_MARGIN') or '1.4')
math.randomseed(seed)
local radius = vcfg.ball.diameter / 2
local counts = { pos = 0, neg = 0, truth = 0 }
-- all the candidates the search can give, not only the ones the detector classifies: more hard
-- negatives (robots' arms and feet, the own body, posts, line crossings) per frame
local cand_cfg = setmetatable({ max_candidates = balldetect.MAXCAND }, { __index = w })

local function write(label, u, v, r, fr)
  balldetect.C.bd_features(fr.yuyv, fr.width, fr.height, u, v, r, margin, feat)
  out:write(string.char(label), ffi.string(feat, 4 * NF))
end

for fr in file:each() do
  p:process(fr.yuyv)
  bd:boundary(p.labels, p.wa, p.ha, w.green, w.boundary_run)
  bd:set_view(fr.cm, fr.pose)
  local b = fr.ball
  local n = bd:candidates(p.labels, p.wa, p.ha, p.scale, w.green, radius, cand_cfg)
  for i = 0, n - 1 do
    local c = bd.cand[i]
    local d = math.sqrt((c.u - b.u) ^ 2 + (c.v - b.v) ^ 2)
    if b.visible >= 0.5 and d <= 0.5 * b.radius then
      write(1, c.u, c.v, c.radius, fr); counts.pos = counts.pos + 1
    elseif b.visible < 0.2 or d > b.radius then
      write(0, c.u, c.v, c.radius, fr); counts.neg = counts.neg + 1
    end
  end
  -- the true ball, where the detector would centre it (a few pixels off), at the radius it expects
  if b.visible >= 0.7 and b.radius >= w.min_radius then
    for _ = 1, 2 do
      local u = b.u + (math.random() - 0.5) * 0.4 * b.radius
      local v = b.v + (math.random() - 0.5) * 0.4 * b.radius
      local r = balldetect.C.bd_ball_radius_px(bd.view, u, v, radius)
      if r > 0 then write(1, u, v, r, fr); counts.truth = counts.truth + 1 end
    end
  end
end
out:close()
print(string.format('%s: %d frames, candidates: %d ball, %d not; %d at the truth', path, file.count, counts.pos,
                    counts.neg, counts.truth))
