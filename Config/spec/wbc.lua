-- What the whole-body skill's values must be (Lib/Config.lua checks it on every load of the wbc
-- concern; the keys and their meaning: Config/common/wbc.lua). The frames and joints against the
-- body are checked where the body is known (the controller refuses an unknown frame by name).
local function finite(x) return type(x) == 'number' and x == x and x ~= math.huge and x ~= -math.huge end

local KINDS = { position = 3, orientation = 9, pose = 12, com = 3, com_xy = 2, posture = true }

local function task(t)
  if type(t) ~= 'table' then return 'must be a table' end
  local count = KINDS[t.kind]
  if not count then return "must be one of position, orientation, pose, com, com_xy, posture", 'kind' end
  local frame_kind = t.kind == 'position' or t.kind == 'orientation' or t.kind == 'pose'
  if frame_kind and type(t.frame) ~= 'string' then return 'must name a frame of the body', 'frame' end
  if type(t.level) ~= 'number' or t.level < 1 or t.level % 1 ~= 0 then return 'must be an integer >= 1', 'level' end
  if not finite(t.gain) or t.gain < 0 then return 'must be a number >= 0 (1/s)', 'gain' end
  if not finite(t.max_rate) or t.max_rate < 0 then return 'must be a number >= 0', 'max_rate' end
  if t.max_accel ~= nil and (not finite(t.max_accel) or t.max_accel < 0) then
    return 'must be a number >= 0 (m/s^2 or rad/s^2; 0: no bound)', 'max_accel'
  end
  local target = t.target
  if target == nil or (target == 'stance' and t.kind == 'com_xy') or (target == 'entry' and t.kind == 'posture') then
    return true
  end
  if count == true and type(target) == 'table' and #target == 0 then
    -- a posture's joints by name (the others keep the entry pose; the names: against the body)
    for j, a in pairs(target) do
      if type(j) ~= 'string' or not finite(a) then return 'must map joint names to finite angles', 'target' end
    end
    return true
  end
  if type(target) ~= 'table' or (count ~= true and #target ~= count) then
    local what = count == true and 'joint angles (or joint = angle)' or tostring(count) .. ' numbers'
    return 'must be a list of ' .. what .. ", 'stance' (com_xy) or 'entry' (posture)", 'target'
  end
  for i = 1, #target do
    if not finite(target[i]) then return 'must be a finite number', 'target.' .. i end
  end
  return true
end

local function tasks(v)
  if type(v) ~= 'table' then return 'must be a table of name = task' end
  for name, t in pairs(v) do
    local ok, sub = task(t)
    if ok ~= true then return ok, tostring(name) .. (sub and '.' .. sub or '') end
  end
  return true
end

local function frames(v)
  if type(v) ~= 'table' or #v < 1 then return 'must list at least one frame' end
  for i, f in ipairs(v) do
    if type(f) ~= 'string' then return 'must be a frame name', i end
  end
  return true
end

local function reach(v)
  if type(v) ~= 'table' then return 'must be a table { level, gain, max_rate }' end
  local ok, sub = task({ kind = 'com', level = v.level, gain = v.gain, max_rate = v.max_rate })
  return ok, sub
end

local function hardness(v)
  if finite(v) and v >= 0 and v <= 1 then return true end
  return 'must be a number in 0..1'
end

local function seconds(v)
  if finite(v) and v > 0 then return true end
  return 'must be a number > 0 (s)'
end

local function lean(v)
  if finite(v) and v >= 0 and v < math.pi / 2 then return true end
  return 'must be a number in 0..pi/2 (rad; 0: no bound)'
end

local function torque(v)
  if type(v) ~= 'table' then
    return 'must be a table { enabled, group, frame, kp, kd, posture_kp, posture_kd, damping, rate_window, ' ..
      'friction, friction_measured, friction_band }'
  end
  if type(v.enabled) ~= 'boolean' then return 'must be true or false', 'enabled' end
  if type(v.group) ~= 'string' then return "must name a joint group of the body ('rarm')", 'group' end
  if type(v.frame) ~= 'string' then return 'must name a frame of the body', 'frame' end
  for _, k in ipairs({ 'kp', 'kd', 'posture_kp', 'posture_kd', 'damping', 'rate_window', 'friction',
    'friction_measured', 'friction_band' }) do
    if not finite(v[k]) or v[k] < 0 then return 'must be a number >= 0', k end
  end
  return true
end

return { contacts = frames, tasks = tasks, reach = reach, hardness = hardness, hold_after = seconds, max_lean = lean,
  torque = torque }
