-- A bent-knee stance for the sim's scenario tests (same pose as Platforms/Sim/stance.h).
local M = {}

function M.pose(knee)
  knee = knee or 0.6
  local a = knee / 2
  return {
    l_hip_pitch = -a, l_knee = knee, l_ank_pitch = a,
    r_hip_pitch = a, r_knee = -knee, r_ank_pitch = -a,
    l_sho_roll = 1.25, r_sho_roll = -1.25, l_el = 0.5, r_el = -0.5,
    head_tilt = -0.3,
  }
end

-- Commands the stance at full hardness through Body.
function M.command(Body)
  local q = M.pose()
  for _, name in ipairs(Body.joint_names()) do
    Body.set_hardness(name, 1)
    Body.set_torque_enable(name, true)
    Body.set_command(name, q[name] or 0)
  end
end

return M
