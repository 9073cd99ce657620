-- stance: the walk's standing posture (feet together, COM between them), reached smoothly from
-- wherever the robot is; then on to what was asked for (walk, kick, sit).
local Walk = require('Motion.walk')

local M = {}

-- the legs (by IK), the arms (the walk config's posture) and the head (motion.head_command)
M.owns = { 'legs', 'arms', 'head' }

function M.entry(c)
  local w = c.walk
  local d = c:scratch('stance')
  d.q0, d.h0, d.qs = d.q0 or {}, d.h0 or {}, d.qs or {}
  -- after a stand-up or a relax, the walk starts over at stance around where the torso is
  if w:is_active() or c.prev ~= 'walk' then
    w:reset(w.uTorso)
    c.balance:reset()
  end
  -- from the last commands after a motion of ours, else (start, limp, lying) from the measured pose
  local prev = c.prev
  local from_cmd = prev == 'walk' or prev == 'kick_left' or prev == 'kick_right' or prev == 'standup_front'
    or prev == 'standup_back' or prev == 'wbc' or prev == 'pattern' or prev == 'touch' or prev == 'teleop'
  for _, i in ipairs(c.own) do
    d.q0[i] = from_cmd and c.q[i] or c.pos[i]
    d.h0[i] = c.h[i]
  end
  d.blend_time = (prev == 'walk' or prev == 'kick_left' or prev == 'kick_right') and 0 or c.p.tStance
end

function M.update(c)
  local p, w = c.p, c.walk
  local d = c:scratch('stance')
  local q0, h0, qs = d.q0, d.h0, d.qs
  -- the whole body's pose for the mass model: the held joints (a waist) where they are
  for i = 1, c.n do qs[i] = c.q[i] end
  c:balance_update()
  w:advance(c.dt)
  w:joint_angles(qs, c.sensors, c.dt)
  c:head_angles(qs)
  w:update_com_offset(qs)
  local s = d.blend_time > 0 and math.min(1, c:since() / d.blend_time) or 1
  local a = s * s * (3 - 2 * s)
  local own = c.own
  for _, i in ipairs(own) do c.q[i] = q0[i] + a * (qs[i] - q0[i]) end
  c:set_hardness(p.hardnessLegs, p.hardnessArms, p.hardnessHead)
  for _, i in ipairs(own) do c.h[i] = h0[i] + a * (c.h[i] - h0[i]) end
  if s < 1 then return nil end
  local want = c.want
  if want == 'walk' or want == 'kick_left' or want == 'kick_right' or want == 'sit' or want == 'wbc'
    or want == 'pattern' or want == 'touch' or want == 'teleop' then
    return want
  end
end

M.Walk = Walk
return M
