-- A walk pattern generated ahead: the walk engine with ZMP preview control
-- (Player/Motion/walk_preview.lua: the cart-table model, Player/Motion/preview.lua) run offline over
-- a footstep plan, its leg IK on the body's kinematics (Lib/kinematics.lua), written as a joint
-- trajectory file (Lib/trajectory.lua) with the planned ZMP, COM and feet; the motion state
-- `pattern` plays it (docs/motion.md).
--   source Run/env.sh; ROBOT=hoap3 luajit Tools/pattern/gen_pattern.lua [OUT.csv]
-- OUT: default build/pattern/<ROBOT>_walk.csv. The plan and the controller's numbers: the body's
-- Config pattern concern (Config/common/pattern.lua, Config/robots/<ROBOT>/pattern.lua); the
-- posture, step height, feet and arms: its walk config. Prints the plan's figures.
-- Columns after the joints: zmp_x, zmp_y (the planned COM's ZMP on the cart-table model), ref_x,
-- ref_y (the ZMP reference the controller tracks), com_x, com_y, lfoot_x, lfoot_y, lfoot_yaw,
-- rfoot_x, rfoot_y, rfoot_yaw, swing_z (m, rad), support (0 both feet, 1 left, 2 right): in the
-- walk's ground frame, its origin midway between the feet at the start, x forward.
local Config = require('Config')
local kin = require('kinematics')
local walk = require('Motion.walk')
local walk_preview = require('Motion.walk_preview')
local trajectory = require('trajectory')

local G = 9.81
local robot = Config.load('robot')
local wp = Config.load('walk')
local pat = Config.load('pattern')
local files = table.concat(Config.files('pattern'), ' + ')

local out = arg[1] or (os.getenv('HRP_ROOT') .. '/build/pattern/' .. robot.name .. '_walk.csv')
local dir = out:match('^(.*)/[^/]*$')
if dir then os.execute("mkdir -p '" .. dir:gsub("'", "'\\''") .. "'") end

local function pick(v, default) if v == false then return default end return v end
local dt = pick(pat.dt, robot.period)
local zc = pick(pat.zc, wp.tZmp * wp.tZmp * G)
local N = pick(pat.samples, math.floor(wp.preview.window / dt + 0.5))
local tStep = pick(pat.tStep, wp.tStep)
local lead = pick(pat.lead, wp.preview.lead)
-- the walk's parameters with the pattern's: the cart height as tZmp, the preview window as N
-- samples of dt (walk_preview rounds window / dt to N)
local preview = { window = N * dt, Qe = pick(pat.Qe, wp.preview.Qe), R = pick(pat.R, wp.preview.R), lead = lead }
local over = { tZmp = math.sqrt(zc / G), tStep = tStep, stepHeight = pick(pat.stepHeight, wp.stepHeight),
  preview = preview }
local p = setmetatable(over, { __index = wp })
if pat.stepLength < wp.stepLimitX[1] or pat.stepLength > wp.stepLimitX[2] then
  error(string.format("%s: key 'stepLength' %.3f m is outside the walk's stepLimitX %.3f..%.3f m", files,
    pat.stepLength, wp.stepLimitX[1], wp.stepLimitX[2]), 0)
end

local model = kin.load()
local w = walk_preview.new(p, model, dt)
w:bind(robot, table.concat(Config.files('walk'), ' + '))
w.dt = dt -- the pattern's sample time, not the motion tick's

-- The footstep plan: step i (1-based, the step that begins) at velocity stepLength / tStep, the
-- last at rest (the closing step, feet together). The engine takes its steps from a velocity; here
-- that velocity is the plan's step by step, without the live walk's rate limit: begin_step() asks
-- for the step that begins (no argument), plan_ahead() for each later step in turn over the
-- preview window (a table of its own), so the whole plan is known a window ahead.
local plan = {}
local T_step = w:step_time({ 0, 0, 0 }) -- tStep in whole samples (Player/Motion/walk_preview.lua)
for i = 1, pat.steps - 1 do plan[i] = pat.stepLength / T_step end
plan[pat.steps] = 0
local ahead = 0
function w.update_velocity(self, v)
  if v == nil or v == self.vel then
    v = self.vel
    ahead = self.stats.steps + 1
  else
    ahead = ahead + 1
  end
  v[1], v[2], v[3] = plan[ahead] or 0, 0, 0
end

-- the joints no walk drives (waist, neck) at 0, the head looking ahead
local n = #robot.joints
local q = {}
for i = 1, n do q[i] = 0 end

local function tick()
  w:advance(dt)
  w:joint_angles(q, nil, dt)
  w:update_com_offset(q)
end

-- stance first: the COM offset of the mass model settles (the torso is placed by it)
for _ = 1, math.floor(2 / dt) do tick() end

local names, extra = robot.joints, { 'zmp_x', 'zmp_y', 'ref_x', 'ref_y', 'com_x', 'com_y', 'lfoot_x', 'lfoot_y',
  'lfoot_yaw', 'rfoot_x', 'rfoot_y', 'rfoot_yaw', 'swing_z', 'support' }
local rows = {}
local function record(t)
  local row = { t }
  for i = 1, n do row[#row + 1] = q[i] end
  -- the reference the controller used this tick (sample k - 1, Player/Motion/walk_preview.lua com_at)
  local rx, ry = w.zmp[1], w.zmp[2]
  if w.ctl and w.ring_size > 0 then
    local i = (w.k - 1) % w.ring_size
    rx, ry = w.ring[1][i] or rx, w.ring[2][i] or ry
  end
  local support = 0
  if w.active and w:single_support() > 0 then support = w.support == walk.LEFT and 1 or 2 end
  local L, R = w.uLeft, w.uRight
  for _, v in ipairs({ w.zmp[1], w.zmp[2], rx, ry, w.com[1], w.com[2], L[1], L[2], L[3], R[1], R[2], R[3],
    w.swing_z, support }) do
    row[#row + 1] = v
  end
  rows[#rows + 1] = row
end

-- the first row: the stance the robot stands in when the pattern begins
record(0)
w:start()
-- the plan ends with the feet together: the walk stops after its last step (Walk:begin_step())
w.stopping = true
-- after the last step the engine lets the controller bring the COM to rest over the feet's middle
-- for `lead` s, then holds it there: with slow weights (R/Q 1e-5) the COM is still a few mm short
-- then and the hold would jump to it in one tick (3.5 mm on the HOAP-3's plan, 1 deg on the ankles).
-- The pattern lets the controller run on until the COM is within 0.1 mm of the middle.
local function settling()
  if not (w.ctl and w.settle == 1) then return end
  local L, R = w.uLeft2, w.uRight2
  local mx, my = 0.5 * (L[1] + R[1]), 0.5 * (L[2] + R[2])
  if math.abs(w.com[1] - mx) > 1e-4 or math.abs(w.com[2] - my) > 1e-4 then w.settle = 2 end
end
local k = 0
local steps_at_end
while true do
  k = k + 1
  settling()
  tick()
  record(k * dt)
  if not w.active and w.settle == 0 and not w.ctl then
    steps_at_end = steps_at_end or k
    if (k - steps_at_end) * dt >= pat.hold then break end
  end
  if k * dt > 600 then error('gen_pattern: the walk did not stop within 600 s', 0) end
end

-- figures: the planned ZMP against the reference, the distance, each joint's peak speed against
-- its drive's (Config actuators: a pattern faster than the drives is not played as planned)
local actuators = Config.load('actuators')
local e2, emax, m = 0, 0, 0
local vpeak = {}
for i = 1, n do vpeak[i] = 0 end
for r = 1, #rows do
  local row = rows[r]
  local ex, ey = row[n + 2] - row[n + 4], row[n + 3] - row[n + 5]
  local e = math.sqrt(ex * ex + ey * ey)
  e2, emax, m = e2 + e * e, math.max(emax, e), m + 1
  if r > 1 then
    for i = 1, n do vpeak[i] = math.max(vpeak[i], math.abs(row[1 + i] - rows[r - 1][1 + i]) / dt) end
  end
end
local worst, wname, wspeed = -1, '', 0
for i = 1, n do
  local act = actuators[robot.actuator[names[i]]]
  local frac = vpeak[i] / act.speed
  if frac > worst then worst, wname, wspeed = frac, names[i], act.speed end
end
local last = rows[#rows]
trajectory.write(out, {
  robot = robot.name, dt = dt, joints = names, extra = extra, rows = rows,
  comments = {
    string.format('made by Tools/pattern/gen_pattern.lua from %s', files),
    string.format('plan: %d steps of %.3f m in %.3f s, z_c %.4f m, T %.4f s, N %d, Qe %g, R %g (R/Q %g)',
      pat.steps, pat.stepLength, tStep, zc, dt, N, preview.Qe, preview.R, preview.R / preview.Qe),
  },
})
print(string.format('# pattern %s: %d rows over %.2f s, %d steps, %.3f m forward', out, #rows, last[1],
  w.stats.steps, 0.5 * (last[n + 8] + last[n + 11])))
print(string.format('# plan: z_c %.3f m, T %.3f s, N %d, R/Q %g; planned ZMP from its reference: RMS %.1f mm, '
  .. 'max %.1f mm', zc, dt, N, preview.R / preview.Qe, 1000 * math.sqrt(e2 / m), 1000 * emax))
print(string.format('# fastest joint for its drive: %s %.2f rad/s, %.0f%% of its %.2f rad/s', wname,
  worst * wspeed, 100 * worst, wspeed))
