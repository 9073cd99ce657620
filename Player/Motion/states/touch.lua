-- touch: the arms of the body's touch config (Config/common/touch.lua, the body's touch.lua over it)
-- move from their commanded pose straight (in joint space) towards their `to` pose at `speed`; each
-- stops where the force at its wrist sensor (dcm.sensor.ft) has stayed `force` above its reading at
-- the start (the hand's weight, whichever way the arm points) for `confirm` s; from then on it
-- presses with `press` N, moving along its path while the force is below that and back while above.
-- An arm that gets to `to` without touching holds `to`. The legs and the rest are held where stance
-- left them. Leaves through stance when another motion is asked for.
local Config = require('Config')

local M = {}

-- dcm.sensor.ft's order: left foot, right foot, left hand, right hand, six values each
local FT_FIRST = { lhand = 13, rhand = 19 }

local function config(c)
  local d = c:scratch('touch')
  if not d.cfg then d.cfg = Config.load('touch', nil, { robot = c.robot.name }) end
  return d.cfg
end

-- the joints of each configured arm, by index (an unknown joint stops the process naming it)
local function arm_joints(c, arm, k)
  local list = {}
  for name in pairs(arm.to) do
    local i = c.ji[name]
    if not i then
      error(string.format("touch config: arms.%d.to names joint '%s', which the body '%s' lacks", k, name,
        c.robot.name), 0)
    end
    list[#list + 1] = i
  end
  table.sort(list)
  return list
end

function M.owns(c)
  local own = {}
  for k, arm in ipairs(config(c).arms) do
    for _, i in ipairs(arm_joints(c, arm, k)) do own[#own + 1] = i end
  end
  return own
end

-- |force| at an arm's wrist sensor, N
local function force_at(c, arm)
  local f = c.ft
  local k = arm.ft
  return math.sqrt(f[k] ^ 2 + f[k + 1] ^ 2 + f[k + 2] ^ 2)
end

function M.entry(c)
  local cfg, d = config(c), c:scratch('touch')
  d.arms = {}
  for k, arm in ipairs(cfg.arms) do
    local joints = arm_joints(c, arm, k)
    local q0, q1, far = {}, {}, 0
    for j, i in ipairs(joints) do
      q0[j], q1[j] = c.q[i], arm.to[c.robot.joints[i]]
      far = math.max(far, math.abs(q1[j] - q0[j]))
    end
    d.arms[k] = { sensor = arm.sensor, ft = FT_FIRST[arm.sensor], joints = joints, q0 = q0, q1 = q1,
      duration = far / cfg.speed, s = 0, above = nil, touched = false, force = 0, at = nil }
    d.arms[k].rest = force_at(c, d.arms[k])
  end
end

function M.update(c)
  local cfg, d = config(c), c:scratch('touch')
  for _, arm in ipairs(d.arms) do
    local f = force_at(c, arm) - arm.rest
    local rate = arm.duration > 0 and 1 / arm.duration or math.huge   -- of s, per s, at `speed`
    local ds
    if arm.touched then
      -- pressing: on while the force is below `press`, back while above, at most at half speed
      ds = 0.5 * rate * math.max(-1, math.min(1, (cfg.press - f) / cfg.press)) * c.dt
    else
      if f > cfg.force then
        arm.above = arm.above or c.t
        if c.t - arm.above >= cfg.confirm then arm.touched, arm.force, arm.at = true, f, c.t end
      else
        arm.above = nil
      end
      ds = arm.touched and 0 or rate * c.dt
    end
    local s = math.max(0, math.min(1, arm.s + ds))
    if s ~= arm.s then
      arm.s = s
      for j, i in ipairs(arm.joints) do c.q[i] = arm.q0[j] + s * (arm.q1[j] - arm.q0[j]) end
    end
  end
  if c.want ~= 'touch' then return 'done' end
end

-- What each arm did: { sensor, touched, force (N over the rest reading, when it stopped), at (robot s),
-- progress (0..1) }.
function M.report(c)
  local out = {}
  for k, arm in ipairs(c:scratch('touch').arms or {}) do
    out[k] = { sensor = arm.sensor, touched = arm.touched, force = arm.force, at = arm.at, progress = arm.s }
  end
  return out
end

return M
