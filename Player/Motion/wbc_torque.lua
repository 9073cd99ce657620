-- Torque mode inside the motion state wbc (Player/Motion/states/wbc.lua): with the skill's
-- torque.enabled (Config/common/wbc.lua, live through param()), the joints of torque.group are
-- driven in torque mode by operational-space control of torque.frame (Lib/wbc_torque.lua over
-- Modules/wbc's solve_torque); the kinematic controller keeps every other joint in position mode.
-- The frame's target is WBC.set_target(frame, { x, y, z }) in the stance frame, or 9 numbers
-- (position, velocity, acceleration: a trajectory's feed-forward); nil: no task (gravity and
-- Coriolis compensation, the posture and the joint damping only). The posture is the limb's angles
-- when torque mode starts. The model's state each tick: the measured joint angles and rates, the
-- base where the kinematic controller has it in the stance frame, tilted as the IMU measures.
-- Switched off (or at the state's exit) the limb goes back to position mode holding where it is.
-- The torques reach the DCM through ctl.tau (Player/Motion/main.lua, Body.drive_torque); the DCM's
-- guard clamps them to the actuators' limits and its watchdog puts every joint back in position mode.
local Body = require('Body')
local wbc_torque = require('wbc_torque')

local atan2 = math.atan2

local M = {}
local T = {}
T.__index = T

-- cfg: the skill (its torque table is read every tick: param changes act at once).
function M.new(c, cfg)
  return setmetatable({ cfg = cfg, robot = c.robot.name, dt = c.robot.period, active = false, hold = nil,
    q = {}, qd = {}, base = {}, b7 = {}, hist = {}, slow = {} }, T)
end

-- The controller of the present group and frame, built when torque mode first starts.
local function controller(t)
  local tc = t.cfg.torque
  if t.ctl and t.ctl.group == tc.group and t.ctl.frame == tc.frame then return t.ctl end
  local joints = Body.group(tc.group)
  t.ctl = wbc_torque.new({ robot = t.robot, joints = joints, frame = tc.frame, dt = t.dt })
  t.ctl.group = tc.group
  t.idx = {}
  for k, name in ipairs(joints) do t.idx[k] = Body.index(name) end
  return t.ctl
end

-- True if targets for `name` are this module's (torque mode on and `name` its frame).
function T:owns(name)
  local tc = self.cfg.torque
  return tc.enabled and name == tc.frame
end

-- A target for the frame: 3 numbers (position), 9 (position, velocity, acceleration) or nil.
function T:set_target(name, target)
  local ctl = controller(self)
  if target == nil then return ctl:target(nil) end
  if #target ~= 3 and #target ~= 9 then
    error(string.format("wbc: '%s' is torque driven: its target is { x, y, z } or 9 numbers (position, velocity, " ..
      'acceleration)', name), 0)
  end
  if #target == 3 then return ctl:target(target) end
  ctl:target({ target[1], target[2], target[3] }, { target[4], target[5], target[6] },
    { target[7], target[8], target[9] })
end

function T:entry()
  self.active, self.hold = false, nil
  if self.ctl then self.ctl:target(nil) end
end

-- The model's base: position and heading from the kinematic controller (stance frame), tilt from the IMU.
local function base(self, c, kin)
  local b = kin:base(self.b7)
  local qx, qy, qz, qw = b[4], b[5], b[6], b[7]
  local yaw = atan2(2 * (qw * qz + qx * qy), 1 - 2 * (qy * qy + qz * qz))
  local out = self.base
  out[1], out[2], out[3], out[4], out[5], out[6] = b[1], b[2], b[3], c.angle[1], c.angle[2], yaw
  return out
end

-- After the kinematic step: the limb's torques into c.tau (and its commands held where it is, so a
-- return to position mode holds it), or, torque mode off, the limb held where it was left.
function T:update(c, kin)
  local tc = self.cfg.torque
  if not tc.enabled then
    if self.active then
      self.active, self.hold = false, {}
      for k, i in ipairs(self.idx) do self.hold[k] = c.pos[i] end
    end
    if self.hold then
      for k, i in ipairs(self.idx) do c.q[i] = self.hold[k] end
    end
    return
  end
  local ctl = controller(self)
  local q, qd = self.q, self.qd
  for i = 1, #c.pos do q[i], qd[i] = c.pos[i], Body.get_velocity(i) end
  if not self.active then
    self.active, self.hold, self.hist = true, nil, {}
    self.posture = {}
    for k, i in ipairs(self.idx) do self.posture[k] = q[i] end
    ctl:target(nil)
  end
  -- the joint damping's rate: the angle's change over tc.rate_window s (the encoders' one count per
  -- control period is 3 mrad/s on the Hubo2+'s arms: the creep the damping is for is that slow)
  local hist, nwin = self.hist, math.max(1, math.floor(tc.rate_window / self.dt + 0.5))
  hist[#hist + 1] = {}
  for k, i in ipairs(self.idx) do hist[#hist][k] = q[i] end
  if #hist > nwin + 1 then table.remove(hist, 1) end
  local slow = self.slow
  for k = 1, #self.idx do slow[k] = (hist[#hist][k] - hist[1][k]) / (math.max(#hist - 1, 1) * self.dt) end
  local tau = ctl:torques(q, qd, base(self, c, kin), tc, self.posture, slow)
  for k, i in ipairs(self.idx) do
    c.tau[i] = tau[k]
    c.q[i] = q[i]
  end
end

-- The frame's task for WBC.status(): entry n + 1 of the state's report (n: the kinematic tasks).
function T:report(r, n)
  if not self.active then
    r.tasks[n + 1] = nil
    return
  end
  local s = self.ctl:status()
  local x = self.status or { name = self.cfg.torque.frame, level = 1, held = false }
  self.status = x
  x.enabled, x.feasible, x.error, x.sigma_min = self.ctl:has_target(), s.feasible, s.error, s.sigma_min
  r.tasks[n + 1] = x
  if not s.feasible and x.enabled then r.feasible = false end
end

return M
