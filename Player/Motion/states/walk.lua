-- walk: the ZMP walk at the commanded velocity; stops into stance when something else is asked.
-- Heading feedback: the IMU's yaw is held to the integral of the commanded turning rate.
local M = {}

-- the legs (by IK), the arms (the walk config's posture and swing) and the head (motion.head_command)
M.owns = { 'legs', 'arms', 'head' }

local function wrap(a) return (a + math.pi) % (2 * math.pi) - math.pi end

function M.entry(c)
  c.walk:start()
  c:scratch('walk').yaw_ref = c.angle[3]
end

function M.update(c)
  local w, v, p = c.walk, c.vel_cmd, c.p
  local d = c:scratch('walk')
  w:set_velocity(v[1], v[2], v[3])
  d.yaw_ref = wrap(d.yaw_ref + w.vel[3] * c.dt)
  local err = wrap(d.yaw_ref - c.angle[3])
  local lim = p.headingMaxCorrection
  -- no wind-up: when the feet cannot turn as fast as asked the reference stays within twice the
  -- error that saturates the correction (left to grow, past pi it wrapped and turned the other way)
  local room = p.headingGain > 0 and 2 * lim / p.headingGain or 0
  if math.abs(err) > room then
    err = err > 0 and room or -room
    d.yaw_ref = wrap(c.angle[3] + err)
  end
  w.va_correction = math.max(-lim, math.min(lim, p.headingGain * err))
  -- stopping: no more turning steps for the heading (a residual error would keep the feet from
  -- ever coming together: the Hubo's side steps leave one)
  if c.want ~= 'walk' then
    w:stop()
    w.va_correction = 0
  end
  c:balance_update()
  local active = w:advance(c.dt)
  -- a kick out of the walk may throw the torso back on purpose: the fall detection allows for it
  c.tilt = w:extra_pitch()
  w:joint_angles(c.q, c.sensors, c.dt)
  c:head_angles(c.q)
  w:update_com_offset(c.q)
  c:set_hardness(c.p.hardnessLegs, c.p.hardnessArms, c.p.hardnessHead)
  if not active then return 'done' end
end

function M.exit(c) c.tilt = 0 end

return M
